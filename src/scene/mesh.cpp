// build_surface_mesh, build_drawn_surface_mesh and transform_mesh; shapes in mesh_procedural.cpp,
// files in mesh_file.cpp.
#include "scene/mesh.h"

#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/mesh_procedural.h"

namespace ps {

namespace {

Result<Mesh> local_mesh(const Surface& s) {
  switch (s.type) {
    case SurfaceType::kPlane: return mesh_detail::make_plane(s.size_mm, s.resolution);
    case SurfaceType::kSphere: return mesh_detail::make_sphere(s.radius_mm, s.resolution);
    case SurfaceType::kTorus:
      return mesh_detail::make_torus(s.radius_mm, s.minor_radius_mm, s.resolution);
    case SurfaceType::kHeightField:
      return mesh_detail::make_height_field(s.heightmap, s.size_mm, s.height_mm, s.resolution);
    case SurfaceType::kMesh: return load_mesh_file(s.mesh_file);
    case SurfaceType::kBox: return mesh_detail::make_box(s.box_size_mm);
    case SurfaceType::kFourd: return mesh_detail::make_fourd_mesh(s);
  }
  return make_error("build_surface_mesh: unknown surface type");
}

// Surface::visual_stretch: positions scaled along the surface's local axes about its centre,
// normals by the inverse (the normal transform of a scaling), bounds recomputed.
void stretch_mesh(Mesh& m, const Surface& s) {
  const glm::dmat3 rot = euler_xyz_deg(s.rotation_deg);
  const glm::dmat3 scale(glm::dvec3(s.visual_stretch.x, 0, 0), glm::dvec3(0, s.visual_stretch.y, 0),
                         glm::dvec3(0, 0, s.visual_stretch.z));
  const glm::dmat3 inverse_scale(glm::dvec3(1.0 / s.visual_stretch.x, 0, 0), glm::dvec3(0, 1.0 / s.visual_stretch.y, 0),
                                 glm::dvec3(0, 0, 1.0 / s.visual_stretch.z));
  const glm::dmat3 to = rot * scale * glm::transpose(rot), to_n = rot * inverse_scale * glm::transpose(rot);
  m.bounds_min = glm::dvec3(std::numeric_limits<double>::infinity());
  m.bounds_max = -m.bounds_min;
  for (glm::vec3& p : m.positions) {
    const glm::dvec3 q = s.center + to * (glm::dvec3(p) - s.center);
    p = glm::vec3(q);
    m.bounds_min = glm::min(m.bounds_min, q);
    m.bounds_max = glm::max(m.bounds_max, q);
  }
  for (glm::vec3& n : m.normals) n = glm::vec3(glm::normalize(to_n * glm::dvec3(n)));
}

}  // namespace

glm::dmat3 euler_xyz_deg(const glm::dvec3& rotation_deg) {
  const glm::dvec3 r = glm::radians(rotation_deg);
  glm::dmat4 m(1.0);
  m = glm::rotate(m, r.z, glm::dvec3(0, 0, 1));
  m = glm::rotate(m, r.y, glm::dvec3(0, 1, 0));
  m = glm::rotate(m, r.x, glm::dvec3(1, 0, 0));
  return glm::dmat3(m);
}

Result<Mesh> build_surface_mesh(const Surface& surface) {
  Result<Mesh> mesh = local_mesh(surface);
  if (!mesh) return mesh;
  // `scale` is documented for mesh surfaces; procedural shapes are sized by their own keys.
  const double scale = surface.type == SurfaceType::kMesh ? surface.scale : 1.0;
  transform_mesh(*mesh, scale, surface.rotation_deg, surface.center);
  return mesh;
}

Result<Mesh> build_drawn_surface_mesh(const Surface& surface) {
  Result<Mesh> mesh = build_surface_mesh(surface);
  if (mesh && surface.visual_stretch != glm::dvec3(1.0)) stretch_mesh(mesh.value(), surface);
  return mesh;
}

void transform_mesh(Mesh& mesh, double scale, const glm::dvec3& rotation_deg,
                    const glm::dvec3& translation) {
  const glm::dmat3 rotation = euler_xyz_deg(rotation_deg);
  for (glm::vec3& p : mesh.positions) {
    p = glm::vec3(rotation * (scale * glm::dvec3(p)) + translation);
  }
  // Uniform scale and a rotation: normals only rotate (a negative scale would flip them and
  // the winding, so it flips both back).
  const double flip = scale < 0.0 ? -1.0 : 1.0;
  for (glm::vec3& n : mesh.normals) n = glm::vec3(glm::normalize(flip * (rotation * glm::dvec3(n))));
  if (scale < 0.0) {
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
      std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
    }
  }
  mesh_detail::compute_bounds(mesh);
}

}  // namespace ps
