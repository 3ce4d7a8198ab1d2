#include "support/raycast.h"

#include <cmath>

#include "scene/camera.h"

namespace ps::test {

Ray pixel_ray(const Scene& s, int px, int py) {
  const double aspect = static_cast<double>(s.render.width) / s.render.height;
  const glm::dmat4 inv = glm::inverse(view_projection(s.camera, aspect));
  const double x = (px + 0.5) / s.render.width * 2.0 - 1.0;
  const double y = 1.0 - (py + 0.5) / s.render.height * 2.0;
  const glm::dvec4 a = inv * glm::dvec4(x, y, -1.0, 1.0), b = inv * glm::dvec4(x, y, 1.0, 1.0);
  Ray r;
  r.origin = glm::dvec3(a) / a.w;
  r.dir = glm::normalize(glm::dvec3(b) / b.w - r.origin);
  return r;
}

std::vector<Mesh> scene_meshes(const Scene& s) {
  std::vector<Mesh> out;
  for (const Surface& surf : s.surfaces) {
    Result<Mesh> m = build_surface_mesh(surf);
    if (m.ok()) out.push_back(std::move(m.value()));
  }
  return out;
}

namespace {

bool ray_hits_box(const Ray& r, const Mesh& m) {
  double t0 = -1e300, t1 = 1e300;
  for (int k = 0; k < 3; ++k) {
    if (r.dir[k] == 0.0) {
      if (r.origin[k] < m.bounds_min[k] - 1e-6 || r.origin[k] > m.bounds_max[k] + 1e-6) return false;
      continue;
    }
    double a = (m.bounds_min[k] - 1e-6 - r.origin[k]) / r.dir[k];
    double b = (m.bounds_max[k] + 1e-6 - r.origin[k]) / r.dir[k];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  return t0 <= t1;
}

void hit_mesh(const Mesh& m, const Ray& r, std::optional<SurfaceHit>& best) {
  for (size_t i = 0; i + 2 < m.indices.size(); i += 3) {
    const glm::dvec3 p0(m.positions[m.indices[i]]), p1(m.positions[m.indices[i + 1]]),
        p2(m.positions[m.indices[i + 2]]);
    const glm::dvec3 e1 = p1 - p0, e2 = p2 - p0, pv = glm::cross(r.dir, e2);
    const double det = glm::dot(e1, pv);
    if (std::abs(det) < 1e-300) continue;
    const glm::dvec3 tv = r.origin - p0;
    const double u = glm::dot(tv, pv) / det;
    if (u < 0.0 || u > 1.0) continue;
    const glm::dvec3 qv = glm::cross(tv, e1);
    const double v = glm::dot(r.dir, qv) / det;
    if (v < 0.0 || u + v > 1.0) continue;
    const double t = glm::dot(e2, qv) / det;
    if (t <= 0.0 || (best && t >= best->t)) continue;
    glm::dvec3 n = (1.0 - u - v) * glm::dvec3(m.normals[m.indices[i]]) +
                   u * glm::dvec3(m.normals[m.indices[i + 1]]) + v * glm::dvec3(m.normals[m.indices[i + 2]]);
    n = glm::normalize(n);
    // The shader flips the normal on back faces (gl_FrontFacing, counter-clockwise front).
    const bool front = det > 0.0;
    best = SurfaceHit{r.origin + t * r.dir, front ? n : -n, t};
  }
}

}  // namespace

std::optional<SurfaceHit> raycast(const std::vector<Mesh>& meshes, const Ray& ray) {
  std::optional<SurfaceHit> best;
  for (const Mesh& m : meshes)
    if (ray_hits_box(ray, m)) hit_mesh(m, ray, best);
  return best;
}

}  // namespace ps::test
