#include "render/surface_geometry.h"

#include <algorithm>
#include <limits>
#include <string>

#include "scene/mesh.h"

namespace ps {

namespace {

Aabb mesh_bounds(const Mesh& m) { return {m.bounds_min, m.bounds_max}; }

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

Result<SurfaceGeometry> make_surface_geometry(const Surface& s, int index, const world::DeformableSurfaces* deformables) {
  SurfaceGeometry g;
  if (s.deform.enabled) {  // the world built it from the same drawn mesh: not built (a file read) twice
    const Mesh* drawn = deformables ? deformables->mesh(index) : nullptr;
    if (!drawn) return make_error("surface " + std::to_string(index) + " is deformable but has no deformed mesh (world::settled_deformables)");
    g.bounds = mesh_bounds(*drawn);  // the rest mesh's: subdividing copies them and no step rewrites them
    g.mesh = GpuMesh::upload(*drawn, true);
    return g;
  }
  auto mesh = build_drawn_surface_mesh(s);
  if (!mesh) return mesh.error();
  g.bounds = mesh_bounds(mesh.value());
  if (!mesh->w4.empty()) {
    g.sheet_positions = mesh->positions;
    g.w4 = mesh->w4;
    g.w_min = *std::min_element(g.w4.begin(), g.w4.end());
    g.w_max = *std::max_element(g.w4.begin(), g.w4.end());
  }
  g.mesh = GpuMesh::upload(mesh.value());
  return g;
}

std::vector<Aabb> bounds_of(std::span<const SurfaceGeometry> surfaces) {
  std::vector<Aabb> out;
  for (const SurfaceGeometry& g : surfaces) out.push_back(g.bounds);
  return out;
}

}  // namespace ps
