#include "render/surface_geometry.h"

#include <algorithm>
#include <limits>
#include <string>

#include "fourd/fourd_mesh.h"
#include "scene/mesh.h"

namespace ps {

namespace {

Aabb mesh_bounds(const Mesh& m) { return {m.bounds_min, m.bounds_max}; }

}  // namespace

double SurfaceGeometry::nearest_w(const glm::dvec3& probe_mm, double fallback) const {
  // The nearest point of the triangles, not the nearest vertex: where two sheets cross in the
  // picture, a probe hovering over one can be nearer a vertex of the other (Roman's crossing,
  // 4 mm over the one seen) and the shadow would then be drawn on the hidden sheet. The w is that
  // triangle's corner nearest the point (its largest barycentric weight), not interpolated: it
  // stays put while the probe moves within the corner's part of the sheet, as the sheet's w is
  // part of the frame key (a changed w redraws every pixel), and the band around it (15 % of the
  // surface's w range) is far wider than a triangle's own change of w.
  double w = fallback, best = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t + 2 < sheet_indices.size(); t += 3) {
    const std::uint32_t i = sheet_indices[t], j = sheet_indices[t + 1], k = sheet_indices[t + 2];
    glm::dvec3 bary(0.0);
    const glm::dvec3 q = fourd::closest_on_triangle(probe_mm, sheet_positions[i], sheet_positions[j], sheet_positions[k], bary);
    const glm::dvec3 d = q - probe_mm;
    const double d2 = glm::dot(d, d);
    if (!(d2 < best)) continue;
    best = d2;
    w = w4[bary.x >= bary.y && bary.x >= bary.z ? i : bary.y >= bary.z ? j : k];
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
    g.sheet_indices = mesh->indices;
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
