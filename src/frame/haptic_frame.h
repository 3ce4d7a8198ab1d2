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
  std::optional<Camera> camera;  // with a sample: the camera to draw with (the maze's follower)
};

// The frame `renderer` draws for `state`: the proxy as drawn (stretched near an Illusion object,
// pressed into a deformable surface), the view's pose, the hand, the 4D sheet, the bodies and the
// markers (charges, bands, the fields' force, the rolling manifold's rubber band). Without a device
// sample the probe stays where the renderer's view (Renderer::view, the session's) holds it.
// Each piece is what the scene declares, so a scene without it draws none: no Illusion stretch or
// deformable surface, the proxy as felt; no [navigation] or rolling surface, the pose the view
// starts with; no 4D surface, no sheet or path; no bodies or charges, no bands or markers (the
// fields' force arrow is a charge scene's, render/world_markers.h); the hand only under the view's
// device flag. So the maze's frames (its cues a uniform or a viscous field over a room, felt and
// not drawn) draw the proxy where the loop holds it under the follow camera, and nothing more
// (tests/maze/maze_gl_test.cpp).
FrameInput haptic_frame_input(const Renderer& renderer, const HapticState& state, const HapticFrameSources& sources);

// The session's step of the world before it draws `input`: the session's deformable surfaces
// (View::deformables, world/deformable_surfaces.h; null: none) step on to session time `time_s`
// (HapticState::time_s) with `probe` (the scene's probe shape) where `input` draws it, pressing
// them; the renderer then uploads what changed. The first step only sets the clock. Nothing
// without a deformable surface or a device sample (an input with no probe).
void step_deformation(world::DeformableSurfaces* surfaces, const Probe& probe, const FrameInput& input, double time_s);

// Where that input draws the probe (the view's probe when it gives none).
glm::dvec3 drawn_probe(const Renderer& renderer, const FrameInput& input);

}  // namespace ps
