// The view: what a session shows of its world, as it stands between two frames. It belongs to the
// session (a window, a replay, the CLI's render, the library), which moves it; a Renderer only draws
// it (docs/architecture.md, "Glossary"). So a renderer rebuilt after an edit, or replaced by a scene
// switch, needs nothing copied over: the session hands the new one its view, or a fresh view of the
// new scene. What a renderer keeps between frames to draw incrementally (the last frame, the
// reference plane, the normal mean, the 4D path's tube) is drawing state and stays in the renderer.
#pragma once

#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "core/result.h"
#include "render/frame_input.h"
#include "render/world_markers.h"
#include "scene/scene.h"
#include "world/deformable_surfaces.h"

namespace ps {

struct View {
  // The scene's probe where the session has it: moved by each frame input and by each frame's
  // displacement (the pseudo-haptic loop: Renderer::render applies FrameStats::displacement).
  Probe probe;
  // The world camera drawn under `pose`, and the scene's light turned with it: carried from pose to
  // pose (render/frame_input.h carried_camera, whose comment says why step by step).
  Camera camera;
  Light light;
  ViewPose pose;
  ProbeSheet sheet;  // the 4D sheet the probe keeps to
  ViewFlags show;
  // The haptic world as the last frame input left it; a fresh view holds the scene's start state
  // (start_frame_input: what `render` shows). Bodies beyond the scene's are neither drawn nor cast.
  std::vector<glm::dvec3> bodies_mm;
  std::vector<WorldMarker> markers;  // charges, bands, the fields' force, the rubber band
  glm::dvec3 device_mm{0.0};         // the hand (drawn with show.device)
  // The bendable polygons of A Virtual Universe §6, as the session steps them
  // (frame/haptic_frame.h step_deformation); the renderer draws them as they stand and uploads
  // each mesh whose version changed. Null: the scene has none.
  std::shared_ptr<world::DeformableSurfaces> deformables;

  // The camera as the device's workspace sees it (before the pose's offset and turn).
  Camera workspace_camera() const { return unposed_camera(camera, pose); }
};

// A fresh view of `scene`: its probe, camera and light, no pose, the world's start state and its
// deformable surfaces settled under the scene's probe (world::settled_deformables), with `show`.
Result<std::shared_ptr<View>> make_view(const Scene& scene, ViewFlags show = {});

// What a frame input gives replaces that part of the view; the camera and light are carried to a
// given pose (the input's camera, if any, is the one drawn under the view's current pose).
void apply_input(View& view, const FrameInput& input);

// What a rebuild of the scene the view shows restarts (TuneSession's reload policy): a file
// reload keeps the probe's motion and the camera; a `set` restarts the probe, and a camera.* key
// the camera too.
struct ViewRestart {
  bool probe = false;
  bool camera = false;
};

// The view of `scene` (an edit or reload of the scene `now` showed): fresh from the scene
// (make_view), with `now`'s flags and, unless restarted, its probe's position and velocity and
// its camera as the workspace sees it: the new view starts with no pose, and the next frame's pose
// (a [navigation] offset, a rolling turn) carries it from there, as it carried the old one.
Result<std::shared_ptr<View>> rebuilt_view(const View& now, const Scene& scene, ViewRestart restart);

}  // namespace ps
