#include "render/surface_geometry.h"

#include <algorithm>
#include <limits>

#include "scene/camera.h"
#include "scene/mesh.h"

namespace ps {

namespace {

Aabb mesh_bounds(const Mesh& m) { return {m.bounds_min, m.bounds_max}; }

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

double SurfaceGeometry::nearest_w(const glm::dvec3& probe_mm, double fallback) const {
  double w = fallback;
  float best = std::numeric_limits<float>::infinity();
  const glm::vec3 probe(probe_mm);
  for (std::size_t v = 0; v < sheet_positions.size(); ++v) {
    const glm::vec3 dv = sheet_positions[v] - probe;
    const float d2 = glm::dot(dv, dv);
    if (d2 < best) best = d2, w = w4[v];
  }
  return w;
}

Result<SurfaceGeometry> make_surface_geometry(const Surface& s, int index, world::DeformableSurfaces& deformables) {
  auto mesh = build_surface_mesh(s);
  if (!mesh) return mesh.error();
  if (s.visual_stretch != glm::dvec3(1.0)) stretch_mesh(mesh.value(), s);
  SurfaceGeometry g;
  g.bounds = mesh_bounds(mesh.value());
  if (!mesh->w4.empty()) {
    g.sheet_positions = mesh->positions;
    g.w4 = mesh->w4;
    g.w_min = *std::min_element(g.w4.begin(), g.w4.end());
    g.w_max = *std::max_element(g.w4.begin(), g.w4.end());
  }
  if (s.deform.enabled)
    g.mesh = GpuMesh::upload(deformables.add(index, mesh.value(), s.deform), true);
  else
    g.mesh = GpuMesh::upload(mesh.value());
  return g;
}

std::vector<Aabb> bounds_of(std::span<const SurfaceGeometry> surfaces) {
  std::vector<Aabb> out;
  for (const SurfaceGeometry& g : surfaces) out.push_back(g.bounds);
  return out;
}

}  // namespace ps
