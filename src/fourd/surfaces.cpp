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

constexpr double kDense = 0.01;  // KnottedArc: polyline step before resampling

// KnottedArc::make's long knot, from the left pole to the right pole (see there): the trefoil
// cut open at t0, its right end run under the knot past x_max and up to l.
std::vector<glm::dvec3> long_knot(double t0, double x_max) {
  constexpr double kDelta = 0.25;   // half the gap in t where the trefoil is cut
  const glm::dvec3 p = trefoil(t0);
  std::vector<glm::dvec3> pts{{p.x - 0.3, p.y, p.z}};  // left pole
  line_to(pts, trefoil(t0 + kDelta), kDense);
  for (double t = t0 + kDelta; t <= t0 + kTwoPi - kDelta; t += 0.002) pts.push_back(trefoil(t));
  const glm::dvec3 end = trefoil(t0 + kTwoPi - kDelta);
  line_to(pts, end, kDense);
  line_to(pts, {end.x, end.y, -1.3}, kDense);
  line_to(pts, {x_max + 0.3, p.y, -1.3}, kDense);
  line_to(pts, {x_max + 0.3, p.y, p.z}, kDense);
  line_to(pts, {x_max + 0.6, p.y, p.z}, kDense);  // right pole
  return pts;
}

// The polyline's points less `origin`, each with its cumulative arc length over the whole; the
// ends exactly on the spinning plane.
KnottedArc arc_of(const std::vector<glm::dvec3>& line, const glm::dvec3& origin) {
  KnottedArc arc;
  std::vector<double> len(line.size(), 0.0);
  for (std::size_t i = 1; i < line.size(); ++i) len[i] = len[i - 1] + glm::length(line[i] - line[i - 1]);
  for (std::size_t i = 0; i < line.size(); ++i) {
    arc.points.push_back(line[i] - origin);
    arc.s.push_back(len[i] / len.back());
    arc.extent = std::max({arc.extent, std::abs(arc.points.back().x), std::abs(arc.points.back().y),
                           std::abs(arc.points.back().z)});
  }
  arc.points.front().z = arc.points.back().z = 0.0;  // exactly on the spinning plane
  return arc;
}

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

// The trefoil cut open at its leftmost point P = T(t0) (least x; a gap of +-delta in t) and
// made a long knot along the line l through P parallel to x: one end runs left along l to the
// left pole; the other drops below every strand (z = -1.3), runs under the knot past its
// rightmost point and rises there to l, the right pole. Closing it along l far away gives the
// trefoil again (no path crosses a strand). From each pole a short lead continues along l,
// then drops straight to the plane c = 0. Untwisted the plane lies just below the knot
// (z = -1.6); twisted, the knotted part turns about l, so the plane lies below everything it
// sweeps (its largest distance from l, + 0.3) and the drops lie beyond its ends along x.
KnottedArc KnottedArc::make(bool twisted) {
  double t0 = 0.0;
  for (double t = 0.0; t < kTwoPi; t += 1e-4)
    if (trefoil(t).x < trefoil(t0).x) t0 = t;
  const glm::dvec3 p = trefoil(t0);
  double x_max = p.x;
  for (double t = 0.0; t < kTwoPi; t += 1e-3) x_max = std::max(x_max, trefoil(t).x);
  const std::vector<glm::dvec3> pts = long_knot(t0, x_max);
  // The knotted part's reach from l, which the twist sweeps around l.
  double reach = 0.0;
  for (const glm::dvec3& q : pts) reach = std::max(reach, std::hypot(q.y - p.y, q.z - p.z));
  const double plane_z = twisted ? p.z - reach - 0.3 : -1.6;
  // Leads along l and the drops to the plane.
  std::vector<glm::dvec3> left{{p.x - 0.6, p.y, plane_z}};
  line_to(left, {p.x - 0.6, p.y, p.z}, kDense);
  const std::size_t twist_first = left.size();  // index of the left pole once joined
  left.insert(left.end(), pts.begin(), pts.end());
  const std::size_t twist_last = left.size() - 1;
  line_to(left, {x_max + 0.9, p.y, p.z}, kDense);
  line_to(left, {x_max + 0.9, p.y, plane_z}, kDense);
  KnottedArc arc = arc_of(left, glm::dvec3(0.5 * (p.x - 0.6 + x_max + 0.9), p.y, plane_z));
  arc.twist_begin = arc.s[twist_first];
  arc.twist_end = arc.s[twist_last];
  arc.axis_c = p.z - plane_z;
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
        const double turn = twists * theta;  // the knotted part turns about l: b = 0, c = axis_c
        const double c = std::cos(turn), s = std::sin(turn), dc = k.z - arc->axis_c;
        k = {k.x, c * k.y - s * dc, arc->axis_c + s * k.y + c * dc};
      }
      // Scaled so the surface fits in [-1, 1]^4.
      return glm::dvec4(k.x, k.y, k.z * std::cos(theta), k.z * std::sin(theta)) / arc->extent;
    }
  }
  return glm::dvec4(0.0);
}

}  // namespace ps::fourd
