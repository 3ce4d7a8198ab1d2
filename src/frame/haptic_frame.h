// The step from the haptic loop's state to a frame (render/frame_input.h), and the session's step
// of the world before it (the deformable surfaces): one function each for every session that draws
// one: run, replay and bench-haptics (app/session/session.h drive_frame), the maze's window and its
// headless frames (maze/maze_frames.h).
#pragma once

#include <optional>

#include "haptics/haptic_loop.h"
#include "render/frame_input.h"
#include "render/renderer.h"

namespace ps {

// What a frame takes from the haptic side besides the loop's state.
struct HapticFrameSources {
  // The hand's coupling to the proxy (HapticLoopParams::forces): how far the drawn probe presses
  // into a deformable surface (world::pressed_position).
  double coupling_n_per_mm = 0.0;
  LiveCharges charges{};  // run's live charges (count 0: none)
  // The maze's frames (docs/maze.md) draw the proxy itself where the loop holds it, under a
  // camera that follows it, and none of the world view: no pressed or stretched position, view
  // pose, hand, sheet, bodies or markers. Its scenes have none of those surfaces, bodies or
  // charges, but its external-force cue pushes with a field whose arrow the world view would
  // draw; a maze's frames stay what its sessions recorded.
  bool proxy_only = false;
  std::optional<Camera> camera;  // with a sample: the camera to draw with (the maze's follower)
};

// The frame `renderer` draws for `state`: the proxy as drawn (stretched near an Illusion object,
// pressed into a deformable surface), the view's pose, the hand, the 4D sheet, the bodies and the
// markers (charges, bands, the fields' force, the rolling manifold's rubber band). Without a device
// sample the probe stays where the renderer's view (Renderer::view, the session's) holds it.
FrameInput haptic_frame_input(const Renderer& renderer, const HapticState& state, const HapticFrameSources& sources);

// The session's step of the world before it draws `input`: the session's deformable surfaces
// (View::deformables, world/deformable_surfaces.h; null: none) step on to session time `time_s`
// (HapticState::time_s) with `probe` (the scene's probe shape) where `input` draws it, pressing
// them; the renderer then uploads what changed. The first step only sets the clock. Nothing
// without a deformable surface or a device sample (an input with no probe), and nothing for the
// maze's proxy-only frames (their scenes have no deformable surface).
void step_deformation(world::DeformableSurfaces* surfaces, const Probe& probe, const FrameInput& input, double time_s);

// Where that input draws the probe (the view's probe when it gives none).
glm::dvec3 drawn_probe(const Renderer& renderer, const FrameInput& input);

}  // namespace ps
