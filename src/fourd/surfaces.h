// Hanson & Zhang's four surfaces embedded in R^4 (their Table 1), as functions of (u, v) in
// [0, 1]^2, before any 4D rotation. Parametrisations and sources: docs/fourd.md.
//   flat torus        (cos 2pi u, sin 2pi u, cos 2pi v, sin 2pi v): on the 3-sphere of radius sqrt 2
//   spun trefoil      Artin spinning of a knotted arc about the plane c = 0 of the half-space c >= 0
//   Roman surface     (2yz, 2xz, 2xy, y^2 - z^2) of the unit sphere's upper hemisphere: an embedded
//                     RP^2 whose image with w dropped is Steiner's Roman surface
//   twist-spun trefoil Zeeman's k-twist spinning: the knotted part turns k times about its axis
//                     while the arc is spun
#pragma once

#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "fourd/spec.h"

namespace ps::fourd {

// Default grid cells (nu, nv): nu * nv = Hanson & Zhang's polygon count (900, 2800, 1600, 2800).
glm::ivec2 default_grid(SurfaceKind kind);
// "flat_torus", "spun_trefoil", "roman", "twist_spun_trefoil" (the scene file's names).
const char* surface_name(SurfaceKind kind);

// The knotted arc both spun surfaces are made of: a long trefoil in the half-space c >= 0 with
// its two ends on the plane c = 0, sampled densely with its arc length. Coordinates (a, b, c);
// the twist axis l is the line b = 0, c = axis_c along a, which the knotted part's two ends
// (the poles) lie on. `twisted`: the plane lies below all the twist sweeps.
struct KnottedArc {
  std::vector<glm::dvec3> points;  // by arc length, first and last on c = 0
  std::vector<double> s;           // arc length fraction of each point, 0 .. 1
  double twist_begin = 0.0, twist_end = 1.0;  // arc fractions of the knotted part's two ends
  double axis_c = 0.0;             // height of the twist axis l above the plane
  double extent = 0.0;             // largest |coordinate|: the surface is divided by it
  static KnottedArc make(bool twisted);
  glm::dvec3 at(double s) const;   // linear between samples
};

// Point of the surface at (u, v) in [0, 1]^2, in R^4 (unrotated). `twists` is used by the
// twist-spun trefoil only; the arc by the two spun surfaces only (may be null for the others).
glm::dvec4 surface_point(SurfaceKind kind, double u, double v, int twists, const KnottedArc* arc);

}  // namespace ps::fourd
