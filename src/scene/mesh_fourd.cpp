// type = "fourd": the render and haptic mesh of a surface embedded in R^4 (docs/fourd.md).
#include "fourd/fourd_mesh.h"
#include "scene/mesh_procedural.h"

namespace ps::mesh_detail {

Result<Mesh> make_fourd_mesh(const Surface& s) {
  Result<fourd::FourdMesh> built = fourd::build_fourd_mesh(s.fourd);
  if (!built) return built.error();
  const fourd::FourdMesh& f = built.value();
  Mesh mesh;
  const double range = f.w_max - f.w_min;
  for (std::size_t i = 0; i < f.vertices.size(); ++i) {
    mesh.positions.emplace_back(s.scale * f.vertices[i].p3);
    mesh.normals.emplace_back(f.normals[i]);
    mesh.w4.push_back(static_cast<float>(f.vertices[i].w));
    mesh.colors.emplace_back(fourd::depth_colour(range > 0.0 ? (f.vertices[i].w - f.w_min) / range : 0.5));
  }
  for (const glm::uvec3& t : f.triangles) mesh.indices.insert(mesh.indices.end(), {t.x, t.y, t.z});
  compute_bounds(mesh);
  return mesh;
}

}  // namespace ps::mesh_detail
