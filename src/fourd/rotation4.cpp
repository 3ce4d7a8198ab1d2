#include "fourd/rotation4.h"

#include <cassert>
#include <cmath>

namespace ps::fourd {

glm::dmat4 plane_rotation(int a, int b, double radians) {
  assert(a >= 0 && b > a && b < 4 && "plane_rotation: axes must satisfy 0 <= a < b <= 3");
  glm::dmat4 m(1.0);
  const double c = std::cos(radians), s = std::sin(radians);
  // glm is column-major: m[column][row]. Column a (the image of e_a) = c e_a + s e_b.
  m[a][a] = c;
  m[a][b] = s;
  m[b][a] = -s;
  m[b][b] = c;
  return m;
}

glm::dmat4 rotation_from_deg(const std::array<double, 6>& degrees) {
  glm::dmat4 r(1.0);
  for (std::size_t i = 0; i < kRotationPlanes.size(); ++i) {
    const auto [a, b] = kRotationPlanes[i];
    r = plane_rotation(a, b, glm::radians(degrees[i])) * r;  // later planes act after earlier ones
  }
  return r;
}

Projected project(const glm::dvec4& p, Projection4 kind, double eye_distance) {
  const glm::dvec3 xyz(p);
  if (kind == Projection4::kOrthographic) return {xyz, p.w};
  assert(p.w < eye_distance && "fourd::project: point at or behind the 4D eye (check the surface's extent)");
  return {xyz * (eye_distance / (eye_distance - p.w)), p.w};
}

glm::dvec4 unproject(const glm::dvec3& p3, double w, Projection4 kind, double eye_distance) {
  if (kind == Projection4::kOrthographic) return {p3, w};
  return {p3 * ((eye_distance - w) / eye_distance), w};
}

}  // namespace ps::fourd
