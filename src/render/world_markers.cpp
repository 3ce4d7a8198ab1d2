#include "render/world_markers.h"

namespace ps {

std::vector<WorldMarker> world_markers(const Scene& scene, const glm::dvec3& probe_mm,
                                       std::span<const glm::dvec3> bodies_mm,
                                       std::span<const ChargeMarker> extra_charges, const glm::dvec3& force_n) {
  std::vector<WorldMarker> out;
  const glm::dvec3 push(0.85, 0.2, 0.15), pull(0.15, 0.35, 0.9);
  auto charge = [&](const glm::dvec3& at, double q) {
    out.push_back({at, at, kChargeMarkerRadiusMm, q > 0.0 ? push : pull});
  };
  bool any_charge = !extra_charges.empty();
  for (const Field& f : scene.fields)
    if (f.type == FieldType::kCharge) {
      charge(f.position, f.charge_n_mm2);
      any_charge = true;
    }
  for (const ChargeMarker& c : extra_charges) charge(c.position, c.charge_n_mm2);
  for (const glm::dvec3& b : bodies_mm) out.push_back({probe_mm, b, kBandRadiusMm, glm::dvec3(0.55, 0.4, 0.25)});
  const double f = glm::length(force_n);
  if (any_charge && f > 0.01) {
    const glm::dvec3 tip = probe_mm + kArrowMmPerN * force_n;
    out.push_back({probe_mm, tip, 0.8, glm::dvec3(0.95, 0.85, 0.2)});
    out.push_back({tip, tip, 1.8, glm::dvec3(0.95, 0.85, 0.2)});  // the head
  }
  return out;
}

std::vector<glm::dvec3> start_positions(const Scene& scene) {
  std::vector<glm::dvec3> out;
  for (const Body& b : scene.bodies) out.push_back(b.position);
  return out;
}

}  // namespace ps
