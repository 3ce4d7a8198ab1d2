#include "render/world_view.h"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

#include "fourd/fourd_mesh.h"  // depth_colour: the probe path on 4D sheets

namespace ps {

namespace {

std::size_t drawn_bodies(const Scene& scene, const View& view) {
  return std::min(view.bodies_mm.size(), scene.bodies.size());
}

}  // namespace

void WorldView::add_path_point(bool on_sheet, double w_fraction, const glm::dvec3& p) {
  if (!on_sheet) {
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

std::vector<SphereCaster> body_casters(const Scene& scene, const std::vector<glm::dvec3>& bodies_mm) {
  std::vector<SphereCaster> out;
  for (std::size_t i = 0; i < std::min(bodies_mm.size(), scene.bodies.size()); ++i)
    out.push_back({bodies_mm[i], scene.bodies[i].radius_mm});
  return out;
}

bool WorldView::empty(const Scene& scene, const View& view) const {
  return drawn_bodies(scene, view) == 0 && view.markers.empty() && !view.show.device && path_.empty();
}

void WorldView::run(const std::string& glsl_root, const SurfacePass& surface, const Frame& fr) {
  if (!ready_) {
    if (!body_view_.init(glsl_root, surface) || !ghost_view_.init(glsl_root, surface)) return;
    ready_ = true;
  }
  const Scene& scene = *fr.scene;
  const View& view = *fr.view;
  ProbeViewPass::Inputs in;
  in.view_proj = fr.view_proj;
  in.light = &view.light;
  for (std::size_t i = 0; i < drawn_bodies(scene, view); ++i) {
    const Body& b = scene.bodies[i];
    const std::size_t m = static_cast<std::size_t>(b.material_index);
    const glm::dvec3& at = view.bodies_mm[i];
    in.probe = ProbeInput{};
    in.probe.capsule = CapsuleShape{at, at, b.radius_mm};
    in.color = m < scene.materials.size() ? scene.materials[m].albedo : ProbeViewPass::kColor;
    body_view_.run(in);
  }
  for (const std::vector<WorldMarker>* list : {static_cast<const std::vector<WorldMarker>*>(&path_), &view.markers})
    for (const WorldMarker& m : *list) {
      in.probe = ProbeInput{};
      in.probe.capsule = CapsuleShape{m.a, m.b, m.radius_mm};
      in.color = m.color;
      body_view_.run(in);
    }
  if (view.show.device) {
    // The probe's shape at the device, faint: where the hand is, against where the proxy is drawn.
    in.probe = fr.probe;
    const glm::dvec3 shift = view.device_mm - fr.probe_mm;
    in.probe.capsule.a += shift;
    in.probe.capsule.b += shift;
    in.probe.model = glm::translate(glm::dmat4(1.0), shift) * in.probe.model;
    in.color = glm::dvec3(0.35, 0.75, 1.0);
    in.alpha = 0.25;
    ghost_view_.run(in);
  }
}

}  // namespace ps
