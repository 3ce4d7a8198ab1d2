#include "frame/haptic_frame.h"

#include "world/deformable.h"

namespace ps {

namespace {

std::vector<WorldMarker> markers(const Scene& scene, const HapticState& state, const glm::dvec3& shown,
                                 const std::vector<glm::dvec3>& bodies, const LiveCharges& live,
                                 const Camera& camera) {
  std::vector<ChargeMarker> charges;
  for (int i = 0; i < live.count; ++i) charges.push_back({live.position[i], live.charge_n_mm2[i]});
  std::vector<WorldMarker> out = world_markers(scene, shown, bodies, charges, state.field_force_n);
  // The rolling manifold's rubber band, while the view rolls with a tether on (docs/fourd.md).
  const std::vector<Surface>& surfaces = scene.surfaces;
  if (state.roll_facet >= 0 && state.sheet_surface >= 0 &&
      static_cast<std::size_t>(state.sheet_surface) < surfaces.size() &&
      surfaces[static_cast<std::size_t>(state.sheet_surface)].fourd.roll.tether_alpha_n_per_mm4 > 0.0)
    out.push_back(rubber_band_marker(shown, camera));
  return out;
}

}  // namespace

FrameInput haptic_frame_input(const Renderer& renderer, const HapticState& state, const HapticFrameSources& sources) {
  FrameInput in;
  if (state.have_sample && sources.camera) in.camera = sources.camera;
  const Scene& scene = renderer.scene();
  // The proxy as drawn: stretched near an Illusion object (visual_position; identity elsewhere),
  // pressed into a deformable surface by the coupling's share of the hand's depth
  // (world::pressed_position), which then dents under it (step_deformation).
  const glm::dvec3 pressed = world::pressed_position(scene, state.contact_surface, state.proxy_mm,
                                                     state.position_mm, sources.coupling_n_per_mm);
  const glm::dvec3 shown = state.have_sample ? visual_position(scene, pressed) : renderer.probe().position;
  if (state.have_sample) {
    in.probe = ProbeMotion{shown, state.velocity_mm_s};
    in.device_mm = state.device_mm;
  }
  in.view = ViewPose{state.view_offset_mm, state.view_rotation};
  in.sheet = ProbeSheet{state.sheet_surface, state.sheet_w4};
  in.bodies_mm.emplace(state.body_mm.begin(), state.body_mm.begin() + state.body_count);
  // The camera this frame will draw with (the view's, carried to this frame's pose).
  const Camera camera = carried_camera(in.camera.value_or(renderer.camera()), renderer.view().pose, *in.view);
  in.markers = markers(scene, state, shown, *in.bodies_mm, sources.charges, camera);
  return in;
}

void step_deformation(world::DeformableSurfaces* surfaces, const Probe& probe, const FrameInput& input, double time_s) {
  if (!surfaces || !input.probe) return;
  Probe pressing = probe;  // the scene's probe shape, where this frame draws it
  pressing.position = input.probe->position_mm;
  pressing.velocity = input.probe->velocity_mm_s;
  surfaces->advance(time_s, pressing);
}

glm::dvec3 drawn_probe(const Renderer& renderer, const FrameInput& input) {
  return input.probe ? input.probe->position_mm : renderer.probe().position;
}

}  // namespace ps
