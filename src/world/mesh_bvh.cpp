#include "world/mesh_bvh.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <tuple>

#include "world/shapes.h"

namespace ps::world {

struct MeshBvh::Geometry {
  std::vector<glm::dvec3> positions;  // mm
  std::vector<glm::dvec3> normals;    // per vertex, welded, unit
  std::vector<glm::uvec3> triangles;
  std::vector<glm::dvec3> face_normals;
};

struct MeshBvh::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<Geometry> geometries;
  bool committed = false;
  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

namespace {

std::string embree_error(RTCDevice device, const char* what) {
  return std::string("haptic scene: Embree ") + what + " failed (error " +
         std::to_string(static_cast<int>(rtcGetDeviceError(device))) + ")";
}

// Weld by exact position: files split vertices along UV seams and hard edges, which would
// leave each side of a seam with its own normal and the force would jump there.
MeshBvh::Geometry make_geometry(const Mesh& mesh) {
  MeshBvh::Geometry g;
  std::map<std::tuple<float, float, float>, std::uint32_t> welded;
  std::vector<std::uint32_t> remap(mesh.positions.size());
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::vec3& p = mesh.positions[i];
    auto [it, added] = welded.try_emplace({p.x, p.y, p.z}, static_cast<std::uint32_t>(g.positions.size()));
    if (added) g.positions.emplace_back(p);
    remap[i] = it->second;
  }
  g.normals.assign(g.positions.size(), glm::dvec3(0.0));
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const glm::uvec3 t{remap[mesh.indices[i]], remap[mesh.indices[i + 1]], remap[mesh.indices[i + 2]]};
    if (t.x == t.y || t.y == t.z || t.x == t.z) continue;  // degenerate after welding
    const glm::dvec3 a = g.positions[t.x], b = g.positions[t.y], c = g.positions[t.z];
    const glm::dvec3 area_normal = glm::cross(b - a, c - a);  // |.| = 2 x area
    const double len = glm::length(area_normal);
    if (!(len > 0.0)) continue;
    g.triangles.push_back(t);
    g.face_normals.push_back(area_normal / len);
    // Area-weighted: large faces dominate the vertex normal, slivers barely count.
    for (int k = 0; k < 3; ++k) g.normals[t[k]] += area_normal;
  }
  for (glm::dvec3& n : g.normals) {
    const double len = glm::length(n);
    n = len > 0.0 ? n / len : glm::dvec3(0.0, 0.0, 1.0);
  }
  return g;
}

struct QueryState {
  const std::vector<MeshBvh::Geometry>* geometries;
  glm::dvec3 p;
  MeshHit best;
  double best_d2;
};

void consider(QueryState& q, std::uint32_t mesh, std::uint32_t tri) {
  ++q.best.visited;
  const MeshBvh::Geometry& g = (*q.geometries)[mesh];
  const glm::uvec3 t = g.triangles[tri];
  const TrianglePoint c = closest_on_triangle(q.p, g.positions[t.x], g.positions[t.y], g.positions[t.z]);
  const glm::dvec3 d = q.p - c.point;
  const double d2 = glm::dot(d, d);
  if (d2 >= q.best_d2) return;
  q.best_d2 = d2;
  q.best.hit = true;
  q.best.mesh = mesh;
  q.best.triangle = tri;
  q.best.point = c.point;
  q.best.face_normal = g.face_normals[tri];
  const glm::dvec3 n = c.barycentric.x * g.normals[t.x] + c.barycentric.y * g.normals[t.y] +
                       c.barycentric.z * g.normals[t.z];
  const double len = glm::length(n);
  q.best.shaded_normal = len > 1e-12 ? n / len : q.best.face_normal;
}

bool point_query_callback(RTCPointQueryFunctionArguments* args) {
  auto& q = *static_cast<QueryState*>(args->userPtr);
  const double before = q.best_d2;
  consider(q, args->geomID, args->primID);
  if (q.best_d2 >= before) return false;
  // Shrink the search sphere to the best distance so far (rounded up: a float radius must not
  // prune a triangle at exactly that distance); true tells Embree the query changed.
  args->query->radius = std::nextafter(static_cast<float>(std::sqrt(q.best_d2)), std::numeric_limits<float>::max());
  return true;
}

}  // namespace

MeshBvh::MeshBvh() : impl_(std::make_unique<Impl>()) {}
MeshBvh::~MeshBvh() = default;
MeshBvh::MeshBvh(MeshBvh&&) noexcept = default;
MeshBvh& MeshBvh::operator=(MeshBvh&&) noexcept = default;

Status MeshBvh::add_mesh(const Mesh& mesh) {
  Impl& m = *impl_;
  if (m.committed) return make_error("haptic scene: MeshBvh::add_mesh after commit()");
  if (!m.device) {
    // One build thread: the machine's cores belong to the render and haptic threads, and a
    // 100 k-triangle build takes well under a second on one.
    m.device = rtcNewDevice("threads=1,set_affinity=0");
    if (!m.device) return make_error("haptic scene: cannot create an Embree device");
    m.scene = rtcNewScene(m.device);
    rtcSetSceneBuildQuality(m.scene, RTC_BUILD_QUALITY_HIGH);  // built once, queried 1000x a second
  }
  Geometry g = make_geometry(mesh);
  if (g.triangles.empty()) return make_error("haptic scene: a mesh has no non-degenerate triangle");
  RTCGeometry geom = rtcNewGeometry(m.device, RTC_GEOMETRY_TYPE_TRIANGLE);
  // Embree-owned buffers: they carry the padding its SIMD loads need past the last vertex.
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                        3 * sizeof(float), g.positions.size()));
  auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                             3 * sizeof(unsigned), g.triangles.size()));
  if (!v || !idx) {
    rtcReleaseGeometry(geom);
    return make_error(embree_error(m.device, "buffer allocation"));
  }
  for (std::size_t i = 0; i < g.positions.size(); ++i)
    for (int k = 0; k < 3; ++k) v[3 * i + k] = static_cast<float>(g.positions[i][k]);
  for (std::size_t i = 0; i < g.triangles.size(); ++i)
    for (int k = 0; k < 3; ++k) idx[3 * i + k] = g.triangles[i][k];
  rtcCommitGeometry(geom);
  const unsigned id = rtcAttachGeometry(m.scene, geom);
  rtcReleaseGeometry(geom);
  if (id != m.geometries.size()) return make_error("haptic scene: unexpected Embree geometry id");
  m.geometries.push_back(std::move(g));
  return ok_status();
}

Status MeshBvh::commit() {
  Impl& m = *impl_;
  if (m.scene) {
    rtcCommitScene(m.scene);
    if (rtcGetDeviceError(m.device) != RTC_ERROR_NONE) return make_error(embree_error(m.device, "BVH build"));
  }
  m.committed = true;
  return ok_status();
}

MeshHit MeshBvh::closest(const glm::dvec3& p, double max_distance_mm, const MeshHit* hint) const {
  const Impl& m = *impl_;
  QueryState q{&m.geometries, p, {}, max_distance_mm * max_distance_mm};
  if (!m.scene || !m.committed || !(max_distance_mm > 0.0)) return q.best;
  if (hint != nullptr && hint->hit && hint->mesh < m.geometries.size() &&
      hint->triangle < m.geometries[hint->mesh].triangles.size()) {
    consider(q, hint->mesh, hint->triangle);  // best so far: only closer triangles replace it
    max_distance_mm = std::min(max_distance_mm, std::sqrt(q.best_d2));
  }
  RTCPointQuery query;
  query.x = static_cast<float>(p.x);
  query.y = static_cast<float>(p.y);
  query.z = static_cast<float>(p.z);
  query.time = 0.0f;
  query.radius = std::isfinite(max_distance_mm)
                     ? std::nextafter(static_cast<float>(max_distance_mm), std::numeric_limits<float>::max())
                     : std::numeric_limits<float>::infinity();
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(m.scene, &query, &context, point_query_callback, &q);
  q.best.distance_mm = q.best.hit ? std::sqrt(q.best_d2) : 0.0;
  return q.best;
}

MeshHit MeshBvh::closest_brute_force(const glm::dvec3& p) const {
  const Impl& m = *impl_;
  QueryState q{&m.geometries, p, {}, std::numeric_limits<double>::infinity()};
  for (std::uint32_t g = 0; g < m.geometries.size(); ++g)
    for (std::uint32_t t = 0; t < m.geometries[g].triangles.size(); ++t) consider(q, g, t);
  q.best.distance_mm = q.best.hit ? std::sqrt(q.best_d2) : 0.0;
  return q.best;
}

std::size_t MeshBvh::mesh_count() const { return impl_->geometries.size(); }

std::size_t MeshBvh::triangle_count() const {
  std::size_t n = 0;
  for (const Geometry& g : impl_->geometries) n += g.triangles.size();
  return n;
}

}  // namespace ps::world
