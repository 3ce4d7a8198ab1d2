#include "fourd/surfaces.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace ps::fourd {
namespace {

constexpr double kTwoPi = 2.0 * M_PI;

// The trefoil (sin t + 2 sin 2t, cos t - 2 cos 2t, -sin 3t): its z spans [-1, 1], its (x, y)
// radius sqrt(5 - 4 cos 3t) spans [1, 3]; z = -1 at t = pi/6 (one of three lowest points).
glm::dvec3 trefoil(double t) {
  return {std::sin(t) + 2.0 * std::sin(2.0 * t), std::cos(t) - 2.0 * std::cos(2.0 * t), -std::sin(3.0 * t)};
}

// Appends the straight segment to `to` in steps of at most `step`.
void line_to(std::vector<glm::dvec3>& pts, const glm::dvec3& to, double step) {
  const glm::dvec3 from = pts.back();
  const int n = std::max(1, static_cast<int>(std::ceil(glm::length(to - from) / step)));
  for (int i = 1; i <= n; ++i) pts.push_back(from + (to - from) * (static_cast<double>(i) / n));
}

// Every 4D coordinate of the spun surfaces is divided by this: the arc's points lie within
// about 6.5 of the twist axis, so the surface fits in [-1.3, 1.3]^4.
constexpr double kArcScale = 5.0;

}  // namespace

glm::ivec2 default_grid(SurfaceKind kind) {
  switch (kind) {
    case SurfaceKind::kFlatTorus: return {30, 30};          // 900
    case SurfaceKind::kSpunTrefoil: return {100, 28};       // 2800 (along the arc x around)
    case SurfaceKind::kRoman: return {40, 40};              // 1600
    case SurfaceKind::kTwistSpunTrefoil: return {100, 28};  // 2800
  }
  return {30, 30};
}

const char* surface_name(SurfaceKind kind) {
  switch (kind) {
    case SurfaceKind::kFlatTorus: return "flat_torus";
    case SurfaceKind::kSpunTrefoil: return "spun_trefoil";
    case SurfaceKind::kRoman: return "roman";
    case SurfaceKind::kTwistSpunTrefoil: return "twist_spun_trefoil";
  }
  return "?";
}

// The trefoil cut open at its lowest point P = T(pi/6) (a gap of +-delta in t) and made a long
// knot along the vertical line l through P: one end drops straight to the bottom pole on l;
// the other drops below every strand (z = -1.3), runs under the knot to radius 3.5 (outside
// every strand), rises there above every strand (z = 1.3) and comes back to l, then up to the
// top pole. Closing it along l far away gives the trefoil again (no path crosses a strand).
// The parts beyond the poles are fixed by the twist: from the bottom pole straight down l to
// the plane; from the top pole up, out to 6.5 from l (beyond the knotted part's reach of ~5.8
// however it turns) and down to the plane. c = z + 2, so c > 0 except at the two ends.
KnottedArc KnottedArc::make() {
  constexpr double kDense = 0.01;   // polyline step before resampling
  constexpr double kDelta = 0.25;   // half the gap in t where the trefoil is cut
  const double t0 = M_PI / 6.0;
  const glm::dvec3 p = trefoil(t0);
  const glm::dvec3 axis(p.x, p.y, 0.0);  // l: (p.x, p.y, z)
  std::vector<glm::dvec3> pts{axis + glm::dvec3(0, 0, -2.0)};
  line_to(pts, axis + glm::dvec3(0, 0, -1.6), kDense);  // bottom pole
  const std::size_t twist_first = pts.size() - 1;
  line_to(pts, trefoil(t0 + kDelta), kDense);
  for (double t = t0 + kDelta; t <= t0 + kTwoPi - kDelta; t += 0.002) pts.push_back(trefoil(t));
  const glm::dvec3 end = trefoil(t0 + kTwoPi - kDelta);
  line_to(pts, end, kDense);
  line_to(pts, {end.x, end.y, -1.3}, kDense);
  // Under the knot along the backward tangent until outside every strand (radius 3 at most).
  const glm::dvec3 tangent = trefoil(t0 - 1e-3) - trefoil(t0 + 1e-3);
  const glm::dvec2 dir = glm::normalize(glm::dvec2(tangent));
  glm::dvec2 q(end);
  while (glm::length(q) < 3.5) q += 0.01 * dir;
  line_to(pts, {q.x, q.y, -1.3}, kDense);
  line_to(pts, {q.x, q.y, 1.3}, kDense);
  line_to(pts, axis + glm::dvec3(0, 0, 1.3), kDense);
  line_to(pts, axis + glm::dvec3(0, 0, 1.5), kDense);  // top pole
  const std::size_t twist_last = pts.size() - 1;
  line_to(pts, axis + glm::dvec3(0, 0, 1.8), kDense);
  const glm::dvec2 out = glm::normalize(glm::dvec2(axis));
  const glm::dvec3 far = axis + glm::dvec3(6.5 * out, 1.8);
  line_to(pts, far, kDense);
  line_to(pts, {far.x, far.y, -2.0}, kDense);
  // Cumulative arc length, then (a, b, c) = (x - p.x, y - p.y, z + 2).
  KnottedArc arc;
  std::vector<double> len(pts.size(), 0.0);
  for (std::size_t i = 1; i < pts.size(); ++i) len[i] = len[i - 1] + glm::length(pts[i] - pts[i - 1]);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    arc.points.push_back(pts[i] - axis + glm::dvec3(0, 0, 2.0));
    arc.s.push_back(len[i] / len.back());
  }
  arc.points.front().z = arc.points.back().z = 0.0;  // exactly on the spinning plane
  arc.twist_begin = arc.s[twist_first];
  arc.twist_end = arc.s[twist_last];
  return arc;
}

glm::dvec3 KnottedArc::at(double u) const {
  assert(!points.empty() && "KnottedArc::at: empty arc (use KnottedArc::make)");
  const auto it = std::upper_bound(s.begin(), s.end(), u);
  if (it == s.begin()) return points.front();
  if (it == s.end()) return points.back();
  const std::size_t i = static_cast<std::size_t>(it - s.begin());
  const double f = (u - s[i - 1]) / std::max(s[i] - s[i - 1], 1e-300);
  return glm::mix(points[i - 1], points[i], f);
}

glm::dvec4 surface_point(SurfaceKind kind, double u, double v, int twists, const KnottedArc* arc) {
  switch (kind) {
    case SurfaceKind::kFlatTorus: {
      const double a = kTwoPi * u, b = kTwoPi * v;
      return {std::cos(a), std::sin(a), std::cos(b), std::sin(b)};
    }
    case SurfaceKind::kRoman: {
      // Upper hemisphere: longitude 2 pi u, colatitude v pi/2; the equator's antipodal points
      // meet in one point of the image (f(-p) = f(p)), closing the hemisphere into RP^2.
      const double lon = kTwoPi * u, colat = 0.5 * M_PI * v;
      const double s = (v == 0.0) ? 0.0 : std::sin(colat);  // exact pole: its triangles drop out
      const double x = s * std::cos(lon), y = s * std::sin(lon), z = std::cos(colat);
      return {2.0 * y * z, 2.0 * x * z, 2.0 * x * y, y * y - z * z};
    }
    case SurfaceKind::kSpunTrefoil:
    case SurfaceKind::kTwistSpunTrefoil: {
      assert(arc != nullptr && "surface_point: the spun surfaces need their KnottedArc");
      glm::dvec3 k = arc->at(u);
      const double theta = kTwoPi * v;
      if (kind == SurfaceKind::kTwistSpunTrefoil && u > arc->twist_begin && u < arc->twist_end) {
        const double turn = twists * theta;  // the knotted part turns about the c axis
        const double c = std::cos(turn), s = std::sin(turn);
        k = {c * k.x - s * k.y, s * k.x + c * k.y, k.z};
      }
      return glm::dvec4(k.x, k.y, k.z * std::cos(theta), k.z * std::sin(theta)) / kArcScale;
    }
  }
  return glm::dvec4(0.0);
}

}  // namespace ps::fourd
