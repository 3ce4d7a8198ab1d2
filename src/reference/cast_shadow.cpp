#include "reference/cast_shadow.h"

#include <algorithm>
#include <cassert>

namespace ps {

double cast_shadow_coverage(const SphereCaster& probe, const glm::dvec3& x, const glm::dvec3& light_dir,
                            double edge_mm) {
  assert(glm::length(light_dir) > 0.0 && "cast_shadow_coverage: the light needs a direction");
  const glm::dvec3 to_light = -glm::normalize(light_dir);
  const glm::dvec3 q = probe.centre - x;
  const double t = glm::dot(q, to_light);
  const double r = probe.radius_mm;
  // The centre behind x (away from the light) and x outside: the ray leaves the sphere behind.
  if (t <= 0.0 && glm::dot(q, q) >= r * r) return 0.0;
  const double rho = glm::length(q - t * to_light);
  const double edge = std::max(edge_mm, 1e-6);
  return std::clamp((r - rho) / edge + 0.5, 0.0, 1.0);
}

double cast_shadow_light(double ambient, double lambert, double coverage) {
  return ambient + (1.0 - ambient) * lambert * (1.0 - coverage);
}

glm::dvec3 cast_shadow_centre(const glm::dvec3& centre, const glm::dvec3& light_dir, const glm::dvec3& plane_point,
                              const glm::dvec3& n) {
  const double s = glm::dot(plane_point - centre, n) / glm::dot(light_dir, n);
  return centre + s * light_dir;
}

double extent_across(const glm::dvec3& dx, const glm::dvec3& dy, const glm::dvec3& dir) {
  const glm::dvec3 l = glm::normalize(dir);
  return std::max(glm::length(dx - glm::dot(dx, l) * l), glm::length(dy - glm::dot(dy, l) * l));
}

}  // namespace ps
