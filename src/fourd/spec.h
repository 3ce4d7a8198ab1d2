// What a scene file says about one surface embedded in 4D (type = "fourd", docs/fourd.md):
// which surface, its 4D orientation, the 4D -> 3D projection, the tessellation and the haptic
// local model. Plain data; src/fourd/fourd_mesh.h turns it into geometry.
#pragma once

#include <array>

#include "fourd/rolling.h"

namespace ps::fourd {

// Hanson & Zhang's four surfaces (their Table 1), parametrisations in docs/fourd.md.
enum class SurfaceKind { kFlatTorus, kSpunTrefoil, kRoman, kTwistSpunTrefoil };
enum class Projection4 { kPerspective, kOrthographic };
// How the proxy's local model is chosen (Hanson & Zhang §4.2): by 4D-depth continuity (eq. 3-4), by
// mesh adjacency in parameter space, or every facet (the nearest-surface model, for comparison).
enum class LocalModelKind { kContinuity, kAdjacency, kNearest };

// Coordinate planes of the six rotations, in the order they are applied (xy first).
inline constexpr std::array<std::array<int, 2>, 6> kRotationPlanes = {
    {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};

struct Spec {
  SurfaceKind kind = SurfaceKind::kFlatTorus;
  Projection4 projection = Projection4::kPerspective;
  // Perspective: the 4D eye sits on the +w axis at this distance from the origin (4D units);
  // it must lie outside the (rotated) surface.
  double eye_distance = 4.0;
  // Rotation angles in the xy, xz, xw, yz, yw, zw planes (degrees), applied in that order.
  std::array<double, 6> rotation_deg{};
  // Grid cells along u and v; 0 = the surface's default (Hanson & Zhang, Table 1 polygon counts).
  int nu = 0, nv = 0;
  int twists = 2;  // twist-spun trefoil: turns of the knotted ball per spin (Zeeman's k)
  LocalModelKind local_model = LocalModelKind::kContinuity;
  // Force suggestions (eq. 5, fourd/suggestion.h): K_p N/mm, K_v N s/mm, look-ahead s; 0 = off.
  double suggest_kp_n_per_mm = 0.0;
  double suggest_kv_n_s_per_mm = 0.0;
  double suggest_lookahead_s = 0.05;
  // Cutaway (Hanson & Zhang §6.3): other sheets within this radius of the line from the eye to the
  // probe, between them, are not drawn, so the probe and its shadow stay in view; 0 = off. mm.
  double cutaway_mm = 0.0;
  // Crossing diagram (Hanson & Zhang §3, Fig. 3b): each vertex is drawn this many mm nearer the eye
  // per unit of w (along its line of sight, so the picture does not move): where two sheets
  // cross, the one nearer the 4D eye wins a band along the crossing and is seen continuous,
  // the other interrupted. 0 = off (plain 3D depth).
  double crossing_diagram_mm = 0.0;
  // Wireframe (Hanson & Zhang, Fig. 5c): the surface drawn as the edges of its triangles, so the
  // probe's w-coloured path (replay --show-path) and the sheets behind show through it.
  bool wireframe = false;
  // The rolling manifold (Hanson & Zhang §6, fourd/rolling.h): the view turns and glides with the
  // proxy's walk over this surface; the tether pulls the hand toward the screen centre.
  RollParams roll;
  bool operator==(const Spec&) const = default;
};

}  // namespace ps::fourd
