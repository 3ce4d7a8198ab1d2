#include "scene/mesh_procedural.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "image/image.h"

namespace ps::mesh_detail {
namespace {

struct SurfacePoint {
  glm::dvec3 position;
  glm::dvec3 normal;
};

// Samples f(u, v) on an (nu+1) x (nv+1) grid, u and v in [0, 1]. Triangles run (u,v) ->
// (u+1,v) -> (u+1,v+1), so they are counter-clockwise seen from the side d/du x d/dv points
// to; every shape below is parametrised so that side is the outside. Triangles with a
// repeated position (the poles of a sphere) are dropped.
Mesh grid_mesh(int nu, int nv, const std::function<SurfacePoint(double, double)>& f) {
  Mesh mesh;
  for (int j = 0; j <= nv; ++j) {
    for (int i = 0; i <= nu; ++i) {
      const SurfacePoint p = f(static_cast<double>(i) / nu, static_cast<double>(j) / nv);
      mesh.positions.emplace_back(p.position);
      mesh.normals.emplace_back(glm::normalize(p.normal));
    }
  }
  auto index = [nu](int i, int j) { return static_cast<std::uint32_t>(j * (nu + 1) + i); };
  auto add = [&mesh](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    const auto& p = mesh.positions;
    if (p[a] == p[b] || p[b] == p[c] || p[a] == p[c]) return;
    mesh.indices.insert(mesh.indices.end(), {a, b, c});
  };
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      add(index(i, j), index(i + 1, j), index(i + 1, j + 1));
      add(index(i, j), index(i + 1, j + 1), index(i, j + 1));
    }
  }
  return mesh;
}

constexpr double kTwoPi = 2.0 * M_PI;

// Grey value of an image pixel: mean of the colour channels (alpha ignored).
double grey(const Image& image, int x, int y) {
  const int colour = image.channels >= 3 ? 3 : 1;
  double sum = 0.0;
  for (int c = 0; c < colour; ++c) sum += image.at(x, y, c);
  return sum / colour;
}

// Bilinear sample at u, v in [0, 1]; v = 0 is the BOTTOM row (image row 0 is the top).
double sample_bilinear(const Image& image, double u, double v) {
  const double x = std::clamp(u, 0.0, 1.0) * (image.width - 1);
  const double y = (1.0 - std::clamp(v, 0.0, 1.0)) * (image.height - 1);
  const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
  const int x1 = std::min(x0 + 1, image.width - 1), y1 = std::min(y0 + 1, image.height - 1);
  const double fx = x - x0, fy = y - y0;
  const double top = grey(image, x0, y0) * (1 - fx) + grey(image, x1, y0) * fx;
  const double bottom = grey(image, x0, y1) * (1 - fx) + grey(image, x1, y1) * fx;
  return top * (1 - fy) + bottom * fy;
}

}  // namespace

Mesh make_plane(glm::dvec2 size_mm, int resolution) {
  return grid_mesh(resolution, resolution, [&](double u, double v) {
    return SurfacePoint{{(u - 0.5) * size_mm.x, (v - 0.5) * size_mm.y, 0.0}, {0.0, 0.0, 1.0}};
  });
}

Mesh make_sphere(double radius_mm, int resolution) {
  const int rings = std::max(2, resolution / 2);
  return grid_mesh(resolution, rings, [&](double u, double v) {
    const double phi = u * kTwoPi;
    const double lat = (v - 0.5) * M_PI;
    // Exact poles so the pole triangles are recognised as degenerate and dropped.
    const double c = (v == 0.0 || v == 1.0) ? 0.0 : std::cos(lat);
    const glm::dvec3 n{c * std::cos(phi), c * std::sin(phi), std::sin(lat)};
    return SurfacePoint{radius_mm * n, n};
  });
}

Mesh make_torus(double major_radius_mm, double minor_radius_mm, int resolution) {
  const int tube = std::max(3, resolution / 2);
  return grid_mesh(resolution, tube, [&](double u, double v) {
    const double a = u * kTwoPi, b = v * kTwoPi;
    const glm::dvec3 n{std::cos(b) * std::cos(a), std::cos(b) * std::sin(a), std::sin(b)};
    const glm::dvec3 ring{major_radius_mm * std::cos(a), major_radius_mm * std::sin(a), 0.0};
    return SurfacePoint{ring + minor_radius_mm * n, n};
  });
}

Mesh make_box(glm::dvec3 size_mm) {
  const glm::dvec3 h = 0.5 * size_mm;
  Mesh mesh;
  // Each face: its outward normal n and two tangents u, v with u x v = n, so the corners
  // c - u - v, c + u - v, c + u + v, c - u + v run counter-clockwise seen from outside.
  for (int axis = 0; axis < 3; ++axis) {
    for (double sign : {-1.0, 1.0}) {
      glm::dvec3 n(0.0), u(0.0), v(0.0);
      n[axis] = sign;
      u[(axis + 1) % 3] = h[(axis + 1) % 3];
      v[(axis + 2) % 3] = sign * h[(axis + 2) % 3];
      const glm::dvec3 c = n * h[axis];
      const auto base = static_cast<std::uint32_t>(mesh.positions.size());
      for (const glm::dvec3& p : {c - u - v, c + u - v, c + u + v, c - u + v}) {
        mesh.positions.emplace_back(p);
        mesh.normals.emplace_back(n);
      }
      mesh.indices.insert(mesh.indices.end(),
                          {base, base + 1, base + 2, base, base + 2, base + 3});
    }
  }
  compute_bounds(mesh);
  return mesh;
}

Result<Mesh> make_height_field(const std::string& image_path, glm::dvec2 size_mm,
                               double height_mm, int resolution) {
  Result<Image> image = read_image(image_path);
  if (!image) return image.error();
  if (image->width < 2 || image->height < 2 || image->channels < 1) {
    return make_error(image_path + ": height field image must be at least 2 x 2 pixels");
  }
  const double step = 1.0 / resolution;
  auto height = [&](double u, double v) { return height_mm * sample_bilinear(*image, u, v); };
  return grid_mesh(resolution, resolution, [&](double u, double v) {
    // Central differences (one-sided at the border) of the sampled height, in mm per mm.
    const double du = (height(std::min(u + step, 1.0), v) - height(std::max(u - step, 0.0), v)) /
                      ((std::min(u + step, 1.0) - std::max(u - step, 0.0)) * size_mm.x);
    const double dv = (height(u, std::min(v + step, 1.0)) - height(u, std::max(v - step, 0.0))) /
                      ((std::min(v + step, 1.0) - std::max(v - step, 0.0)) * size_mm.y);
    return SurfacePoint{{(u - 0.5) * size_mm.x, (v - 0.5) * size_mm.y, height(u, v)},
                        {-du, -dv, 1.0}};
  });
}

void compute_bounds(Mesh& mesh) {
  if (mesh.positions.empty()) {
    mesh.bounds_min = mesh.bounds_max = glm::dvec3(0.0);
    return;
  }
  mesh.bounds_min = glm::dvec3(mesh.positions[0]);
  mesh.bounds_max = mesh.bounds_min;
  for (const glm::vec3& p : mesh.positions) {
    mesh.bounds_min = glm::min(mesh.bounds_min, glm::dvec3(p));
    mesh.bounds_max = glm::max(mesh.bounds_max, glm::dvec3(p));
  }
}

}  // namespace ps::mesh_detail
