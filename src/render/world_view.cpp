#include "render/world_view.h"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

#include "fourd/fourd_mesh.h"  // depth_colour: the probe path on 4D sheets

namespace ps {

void WorldView::set_bodies(const std::vector<glm::dvec3>& positions, std::size_t scene_bodies) {
  body_mm_.assign(positions.begin(), positions.begin() + std::min(positions.size(), scene_bodies));
}

void WorldView::add_path_point(bool on_sheet, double w_fraction, const glm::dvec3& p) {
  if (!show_path_ || !on_sheet) {
    path_break_ = true;  // off every sheet (lifted): the path starts a new piece
    return;
  }
  const glm::dvec3 colour = fourd::depth_colour(w_fraction);
  // A tube from the last point, unless the probe left the sheet since (lifted and put down).
  constexpr double kPathRadiusMm = 0.6;
  const bool joined = !path_.empty() && !path_break_;
  path_break_ = false;
  if (joined && glm::length(p - path_.back().b) < 0.25) return;  // closer than a segment is worth
  path_.push_back({joined ? path_.back().b : p, p, kPathRadiusMm, colour});
}

std::vector<SphereCaster> WorldView::body_casters(const Scene& scene) const {
  std::vector<SphereCaster> out;
  for (std::size_t i = 0; i < body_mm_.size(); ++i) out.push_back({body_mm_[i], scene.bodies[i].radius_mm});
  return out;
}

void WorldView::run(const std::string& glsl_root, const SurfacePass& surface, const Frame& fr) {
  if (!ready_) {
    if (!body_view_.init(glsl_root, surface) || !ghost_view_.init(glsl_root, surface)) return;
    ready_ = true;
  }
  const Scene& scene = *fr.scene;
  ProbeViewPass::Inputs in;
  in.view_proj = fr.view_proj;
  in.light = fr.light;
  for (std::size_t i = 0; i < body_mm_.size(); ++i) {
    const Body& b = scene.bodies[i];
    const std::size_t m = static_cast<std::size_t>(b.material_index);
    in.probe = ProbeInput{};
    in.probe.capsule = CapsuleShape{body_mm_[i], body_mm_[i], b.radius_mm};
    in.color = m < scene.materials.size() ? scene.materials[m].albedo : ProbeViewPass::kColor;
    body_view_.run(in);
  }
  for (const std::vector<WorldMarker>* list : {&path_, &markers_})
    for (const WorldMarker& m : *list) {
      in.probe = ProbeInput{};
      in.probe.capsule = CapsuleShape{m.a, m.b, m.radius_mm};
      in.color = m.color;
      body_view_.run(in);
    }
  if (show_device_) {
    // The probe's shape at the device, faint: where the hand is, against where the proxy is drawn.
    in.probe = fr.probe;
    const glm::dvec3 shift = device_mm_ - fr.probe_mm;
    in.probe.capsule.a += shift;
    in.probe.capsule.b += shift;
    in.probe.model = glm::translate(glm::dmat4(1.0), shift) * in.probe.model;
    in.color = glm::dvec3(0.35, 0.75, 1.0);
    in.alpha = 0.25;
    ghost_view_.run(in);
  }
}

}  // namespace ps
