#include "reference/body_shadow.h"

#include "reference/modulation.h"

#include <algorithm>
#include <cmath>

namespace ps {

double body_shadow_radius_mm(double height_mm, double radius_mm, double influence_mm) {
  // The sphere meets the normal through a point at lateral distance rho at the heights
  // height -+ sqrt(r^2 - rho^2). Lowest height < influence: rho^2 < r^2 - (height - influence)^2
  // (when height > influence); highest height >= 0: rho^2 <= r^2 - height^2 (when height < 0).
  const double excess = std::max({height_mm - influence_mm, -height_mm, 0.0});
  return std::sqrt(std::max(radius_mm * radius_mm - excess * excess, 0.0));
}

double body_shadow_darkening(const Material& m, const SphereCaster& body, const glm::dvec3& x,
                             const glm::dvec3& n, double edge_mm) {
  const glm::dvec3 q = body.centre - x;
  const double height = glm::dot(q, n);
  const double rho = glm::length(q - height * n);
  const double r = body.radius_mm;
  const double disc = body_shadow_radius_mm(height, r, m.influence_distance_mm);
  // The disc's edge box-filtered over one pixel (a ramp across it), and never more than a
  // pixel-wide segment of the disc covers (2R / edge), so a vanishing disc fades to nothing.
  const double edge = std::max(edge_mm, 1e-6);
  const double coverage = std::clamp(std::min((disc - rho) / edge + 0.5, 2.0 * disc / edge), 0.0, 1.0);
  if (coverage <= 0.0) return 0.0;
  // Pixels of the filtered rim outside the disc take the intensity at its edge.
  const double rho_in = std::min(rho, disc);
  const double d = height - std::sqrt(std::max(r * r - rho_in * rho_in, 0.0));
  // The intensity curve without its influence cut: the disc already ends where d reaches it.
  const double intensity =
      d <= 0.0 ? 1.0 : intensity_curve(m, d);
  return coverage * intensity;
}

double body_shadows_darkening(const Material& m, std::span<const SphereCaster> bodies,
                              const glm::dvec3& x, const glm::dvec3& n, double edge_mm) {
  double light = 1.0;
  for (const SphereCaster& b : bodies) light *= 1.0 - body_shadow_darkening(m, b, x, n, edge_mm);
  return 1.0 - light;
}

}  // namespace ps
