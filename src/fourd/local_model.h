// The proxy's local model on a surface embedded in 4D (Hanson & Zhang §4.2) and the sticky-stylus
// proxy that keeps to it (§4.1). Geometry: the FourdMesh's 3D image times `scale_mm`, so
// positions are in mm; w is the 4D depth (4D units).
//   kContinuity: eq. 3-4. Starting at the proxy's facet, facets are added while their w range
//                meets [w_cur - D, w_cur + D], D = |w_cur - w_pre| + w_slack, walking from a
//                facet to the facets whose 3D bounding boxes touch it (4D proximity only: no
//                mesh connectivity), within radius_mm of the contact point.
//   kAdjacency:  Hanson & Zhang's alternative: the facets reached through shared mesh edges (the
//                surface's parameter-space topology, FourdMesh::neighbours) within radius_mm
//                measured along the surface (facet centroid to centroid), not through space.
//   kNearest:    every facet: the nearest-surface model, which jumps between sheets where the
//                3D image crosses itself (for comparison).
// w_slack is not in the paper: eq. 4 alone has D = 0 when the proxy rests, which admits no facet
// beyond the current one. Its default is twice the median |w change| along a mesh edge, so the
// window takes in a couple of facets' worth of the sheet's own w change and nothing of a
// sheet that crosses it with a larger w gap (docs/fourd.md).
// No allocation after construction: the haptic thread may call SheetProxy::update every tick.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "fourd/fourd_mesh.h"

namespace ps::fourd {

struct LocalModelParams {
  // Continuity: facets whose boxes lie farther than this from the contact point are left out;
  // adjacency: facets farther than this along the surface.
  double radius_mm = 20.0;
  double w_slack = -1.0;     // < 0: automatic (twice the median |w change| along a mesh edge)
};

class LocalModel {
 public:
  // `mesh` must outlive the model. `scale_mm`: mm per 4D unit of the 3D image; `center_mm`
  // and `rotation`: the surface's placement in the scene (as build_surface_mesh applies them).
  LocalModel(const FourdMesh& mesh, double scale_mm, const glm::dmat3& rotation = glm::dmat3(1.0),
             const glm::dvec3& center_mm = glm::dvec3(0.0));

  // The facets of the local model around `facet` (see the header comment).
  std::span<const int> build(LocalModelKind kind, int facet, const glm::dvec3& contact_mm, double w_cur,
                             double w_pre, const LocalModelParams& params);
  double auto_w_slack() const { return auto_w_slack_; }
  std::size_t facet_count() const { return mesh_.triangles.size(); }
  const FourdMesh& mesh() const { return mesh_; }
  const glm::dvec3& position_mm(std::uint32_t vertex) const { return positions_[vertex]; }
  // Closest point on facet f to p (mm) and the w there (barycentric).
  struct FacetPoint {
    glm::dvec3 point{0.0};
    double w = 0.0;
    double distance_mm = 0.0;
  };
  FacetPoint closest_on_facet(int f, const glm::dvec3& p) const;

 private:
  bool within(int f, const glm::dvec3& c, double r) const;  // bounding-box distance test
  // The constructor's touching_: facets whose boxes (grown by `grow`) touch, through a grid of
  // `cell`-wide cells from `lo`.
  void find_touching(const glm::dvec3& lo, double grow, double cell);
  // build()'s rule for a facet reached from facet `from`: within the radius (along the surface
  // for adjacency), and in the w window for continuity.
  struct Admission {
    LocalModelKind kind;
    glm::dvec3 contact_mm;
    double w_cur, half;  // the w window: w_cur +- half
    const LocalModelParams& params;
  };
  void admit(const Admission& a, int f, std::size_t from);

  const FourdMesh& mesh_;
  std::vector<glm::dvec3> positions_;                // per vertex, mm
  std::vector<glm::dvec3> box_min_, box_max_;        // per facet, mm
  std::vector<std::vector<int>> touching_;           // per facet: facets whose boxes touch it
  std::vector<int> out_;                             // the last model
  std::vector<std::uint32_t> mark_;                  // BFS visit stamp per facet
  std::vector<double> path_mm_;                      // kAdjacency: distance along the surface, mm
  std::vector<glm::dvec3> centroid_;                 // per facet, mm
  std::uint32_t stamp_ = 0;
  double auto_w_slack_ = 0.0;
};

// The sticky stylus of Hanson & Zhang §4.1 on the local model: each tick the proxy moves to the
// closest point of the local model to the device, and w_pre, w_cur follow (eq. 3, step 5).
struct ProxyState {
  int facet = -1;
  glm::dvec3 contact_mm{0.0};
  double w_cur = 0.0, w_pre = 0.0;
  std::size_t local_facets = 0;  // size of the local model used this tick
};

class SheetProxy {
 public:
  SheetProxy(LocalModel& model, LocalModelKind kind, const LocalModelParams& params = {})
      : model_(model), kind_(kind), params_(params) {}
  // Attaches the proxy to the closest point of the whole surface to `device_mm`.
  void reset(const glm::dvec3& device_mm);
  // One servo tick (Hanson & Zhang §4.2 steps 1-5).
  const ProxyState& update(const glm::dvec3& device_mm);
  const ProxyState& state() const { return state_; }

 private:
  LocalModel& model_;
  LocalModelKind kind_;
  LocalModelParams params_;
  ProxyState state_;
};

}  // namespace ps::fourd
