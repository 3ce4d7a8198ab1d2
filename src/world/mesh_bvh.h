// Triangle meshes of the haptic scene in an Embree 3 BVH, queried for the closest point
// (rtcPointQuery with a user callback) on the haptic thread. Embree does the traversal and the
// pruning by the query radius; the distance to each candidate triangle is computed here in
// double precision, and the force-shading normal is interpolated from welded vertex normals
// at the barycentric coordinates of the closest point (A Virtual Universe §6: the normal follows
// the surface across polygon edges, so a coarse mesh feels smooth).
// Thread safety: build on one thread, then closest() from any number of threads (Embree's
// committed scenes are read-only); closest() does not allocate.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "core/result.h"
#include "scene/mesh.h"

namespace ps::world {

struct MeshHit {
  bool hit = false;
  std::uint32_t mesh = 0;       // index in the order add_mesh() was called
  std::uint32_t triangle = 0;
  glm::dvec3 point{0.0};        // mm, world space
  glm::dvec3 face_normal{0.0, 0.0, 1.0};    // outward (counter-clockwise winding)
  glm::dvec3 shaded_normal{0.0, 0.0, 1.0};  // interpolated vertex normal, outward
  double distance_mm = 0.0;
  std::uint32_t visited = 0;    // triangles the query examined (its local model)
};

class MeshBvh {
 public:
  MeshBvh();
  ~MeshBvh();
  MeshBvh(MeshBvh&&) noexcept;
  MeshBvh& operator=(MeshBvh&&) noexcept;
  MeshBvh(const MeshBvh&) = delete;
  MeshBvh& operator=(const MeshBvh&) = delete;

  // Before commit(). Vertices with identical positions are welded for the shading normals.
  Status add_mesh(const Mesh& mesh);
  Status commit();  // builds the BVH; closest() needs it

  // Closest point on any mesh within max_distance_mm of p (hit = false if none). `hint`: a
  // hit of a nearby earlier query (local model by continuity, Hanson & Zhang §4.2): its
  // triangle's distance starts the search radius, so Embree prunes almost every other leaf
  // when p has moved little. The result is the same with or without it.
  MeshHit closest(const glm::dvec3& p, double max_distance_mm, const MeshHit* hint = nullptr) const;
  // The same by testing every triangle (reference for tests and the benchmark).
  MeshHit closest_brute_force(const glm::dvec3& p) const;

  std::size_t mesh_count() const;
  std::size_t triangle_count() const;

  struct Geometry;  // one mesh: positions, welded normals, triangles (mesh_bvh.cpp)

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ps::world
