// Stand-ins for what the WebAssembly builds leave out (web/build_page.sh, tools/web_core_probe.sh):
// mesh files (assimp) and the Embree BVH, neither built for WebAssembly. Each says so when reached:
// a scene with a mesh file is refused by name, and the probe's scene has none (a plane and a
// sphere probe).
#include "scene/mesh.h"
#include "world/mesh_bvh.h"

namespace ps {
Result<Mesh> load_mesh_file(const std::string& p) { return make_error("WebAssembly build: no mesh files (assimp) for " + p); }
namespace world {
struct MeshBvh::Impl {};
MeshBvh::MeshBvh() {}
MeshBvh::MeshBvh(MeshBvh&&) noexcept {}
MeshBvh& MeshBvh::operator=(MeshBvh&&) noexcept { return *this; }
MeshBvh::~MeshBvh() {}
Status MeshBvh::add_mesh(const Mesh&) { return make_error("WebAssembly build: no mesh BVH (Embree)"); }
Status MeshBvh::commit() { return ok_status(); }
MeshHit MeshBvh::closest(const glm::dvec3&, double, const MeshHit*) const { return {}; }
std::size_t MeshBvh::triangle_count() const { return 0; }
}  // namespace world
}  // namespace ps
