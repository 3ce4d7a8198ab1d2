// Stand-ins for what the WebAssembly probe leaves out (tools/web_core_probe.sh): the image reader
// (libpng), mesh files (assimp) and the Embree BVH. Each says so when
// reached; the probe's scene needs none of them (a plane and a sphere probe).
#include "image/image.h"
#include "scene/mesh.h"
#include "world/mesh_bvh.h"

namespace ps {
Result<Image> read_image(const std::string& p) { return make_error("web core probe: no image reader for " + p); }
Result<Mesh> load_mesh_file(const std::string& p) { return make_error("web core probe: no mesh files (" + p + ")"); }
namespace world {
struct MeshBvh::Impl {};
MeshBvh::MeshBvh() {}
MeshBvh::MeshBvh(MeshBvh&&) noexcept {}
MeshBvh& MeshBvh::operator=(MeshBvh&&) noexcept { return *this; }
MeshBvh::~MeshBvh() {}
Status MeshBvh::add_mesh(const Mesh&) { return make_error("web core probe: no mesh BVH (Embree)"); }
Status MeshBvh::commit() { return ok_status(); }
MeshHit MeshBvh::closest(const glm::dvec3&, double, const MeshHit*) const { return {}; }
std::size_t MeshBvh::triangle_count() const { return 0; }
}  // namespace world
}  // namespace ps
