// The haptic side of a surface embedded in 4D: its projected triangles in world space (mm)
// with the 4D depth w of every vertex, in a uniform grid, queried for the closest point on the
// haptic thread (docs/fourd.md, "Touching the 4D-continuous sheet"). A query may carry a w
// window: then only facets whose w range meets it count, so a sheet that crosses the proxy's
// sheet in the 3D image (at another w) is not there for the proxy: it slides through it as
// through a ghost (Hanson & Zhang §4.2, eq. 3-4, the local model by 4D-depth continuity).
// Built once per haptic scene; closest() is const, thread-safe and allocation-free.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "fourd/fourd_mesh.h"

namespace ps::fourd {

struct WWindow {
  bool active = false;  // false: every facet (the nearest-surface model)
  double lo = 0.0, hi = 0.0;
};

struct TouchHit {
  bool hit = false;
  int facet = -1;
  glm::dvec3 point{0.0};                     // mm, world space
  glm::dvec3 normal{0.0, 0.0, 1.0};          // face normal, turned toward the query point
  glm::dvec3 shaded_normal{0.0, 0.0, 1.0};   // interpolated vertex normal, same side
  double w = 0.0;                            // 4D depth at the point (barycentric)
  double distance_mm = 0.0;
  std::uint32_t visited = 0;                 // facets examined (the local model's size)
};

class FourdTouch {
 public:
  // `scale_mm`, `rotation`, `center_mm`: the surface's placement (as build_surface_mesh).
  FourdTouch(const FourdMesh& mesh, double scale_mm, const glm::dmat3& rotation, const glm::dvec3& center_mm);

  TouchHit closest(const glm::dvec3& p, double max_distance_mm, const WWindow& window = {}) const;
  // The local model by mesh adjacency (the alternative of Hanson & Zhang §4.2, fourd_local_model =
  // "adjacency"): only the facets reached from `start_facet` through shared mesh edges within
  // `radius_mm` along the surface (from `start_point`, then centroid to centroid), at most
  // kMaxAdjacent of them. A sheet that crosses this one in the 3D image is near in space but
  // far along the surface: it is not there. Allocation-free (fixed storage on the stack).
  static constexpr std::size_t kMaxAdjacent = 1024;
  TouchHit closest_adjacent(const glm::dvec3& p, double max_distance_mm, int start_facet,
                            const glm::dvec3& start_point, double radius_mm) const;
  // The window of eq. 4 around w_cur: half-width |w_cur - w_pre| + w_slack().
  WWindow window(double w_cur, double w_pre) const;
  double w_slack() const { return w_slack_; }

  // The nearest facet within max_distance_mm of p whose w range misses `window` (another
  // sheet), p's signed distance from its plane along its face normal (the parameter grid's
  // winding, not turned toward p: the sign says which side p is on), and the w there.
  struct OtherSheet {
    bool hit = false;
    int facet = -1;
    double signed_mm = 0.0;
    double w = 0.0;
  };
  OtherSheet other_sheet(const glm::dvec3& p, double max_distance_mm, const WWindow& window) const;
  // The same facet, or two facets sharing a vertex of the image (for the crossing detector).
  bool facets_touch(int a, int b) const;
  std::size_t facet_count() const { return tris_.size(); }
  // Facet f's unit normal by the parameter grid's winding (either side of the image), mm space.
  glm::dvec3 facet_normal(int f) const;

 private:
  struct Tri {
    glm::uvec3 v;
    double w_min, w_max;
    glm::ivec3 cell_lo, cell_hi;  // grid cells its box overlaps
  };
  glm::ivec3 cell_of(const glm::dvec3& p) const;
  void build_grid(const FourdMesh& mesh);  // the constructor's tris_, cell_start_, cell_facets_
  // Calls visit(facet index, its Tri) once for every facet whose grid cells overlap the box of
  // half size r around p (a facet in several cells: in the first of them the walk meets).
  template <class Visit>
  void for_each_facet_near(const glm::dvec3& p, double r, Visit&& visit) const;

  void finish(TouchHit& hit, const glm::dvec3& p) const;  // the hit's normals, on p's side
  std::vector<glm::dvec3> positions_, normals_;
  std::vector<glm::ivec3> neighbours_;  // per facet, across its edges (FourdMesh::neighbours)
  std::vector<glm::dvec3> centroid_;    // per facet, mm
  std::vector<double> w_;
  std::vector<Tri> tris_;
  glm::dvec3 origin_{0.0};
  double cell_mm_ = 1.0;
  glm::ivec3 dims_{1};
  std::vector<std::uint32_t> cell_start_;  // CSR: facets of cell c are cell_facets_[start[c] .. start[c+1])
  std::vector<std::uint32_t> cell_facets_;
  double w_slack_ = 0.0;
};

}  // namespace ps::fourd
