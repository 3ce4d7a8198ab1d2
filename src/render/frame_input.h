// What one frame changes of the view (render/view.h) before it is drawn: the probe, the camera and
// pose, the hand, the 4D sheet, the bodies and the markers (Renderer::render). Built from the haptic
// state by frame/haptic_frame.h (run, replay, the maze, bench-haptics), or by hand (the tests,
// calibrate, bench).
//
// Every member left empty keeps what the view holds: the probe where the last frame's displacement
// left it (the pseudo-haptic loop), the camera it was given, and the world (bodies, markers, hand)
// until another input replaces it.
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "render/world_markers.h"
#include "scene/scene.h"

namespace ps {

// The view's pose (HapticState::view_offset_mm and view_rotation): world = rotation * workspace +
// offset. [navigation] moves it, a rolling fourd surface turns it (fourd/rolling.h).
struct ViewPose {
  glm::dvec3 offset_mm{0.0};
  glm::dmat3 rotation{1.0};
  bool operator==(const ViewPose&) const = default;
};

// A camera drawn under pose `from`, carried to pose `to`: x -> R_to R_from^T (x - t_from) + t_to
// (its up turned only when the rotation changed). The renderer carries its camera from frame to
// frame this way, step after step. Computing it afresh from the workspace camera and the pose
// each frame (R x + t) is the cleaner model, but it is not the same bits: on the rolling walk
// (tests/fourd/data/flat_torus_roll.traj) the camera's last bits reach the haptic loop through
// the published view axes, and the proxy leaves the surface 3 ticks later (2418 instead of
// 2415); every replay's frames and event log stay byte-identical this way.
Camera carried_camera(const Camera& camera, const ViewPose& from, const ViewPose& to);
// A direction (the light's) carried alike; unchanged unless the rotation changed.
glm::dvec3 carried_direction(const glm::dvec3& direction, const ViewPose& from, const ViewPose& to);
// The workspace camera a world camera drawn under `pose` comes from: R^T (x - t).
Camera unposed_camera(const Camera& world, const ViewPose& pose);

struct ProbeMotion {
  glm::dvec3 position_mm{0.0};
  glm::dvec3 velocity_mm_s{0.0};
};

// The sheet of a surface embedded in 4D the probe keeps to (HapticState::sheet_surface, sheet_w4).
// surface -1: the sheet of the vertex nearest the probe.
struct ProbeSheet {
  int surface = -1;
  double w4 = 0.0;
};

// What is drawn over the pseudo-shadow besides the world (colour only: never the AOVs, the
// reference plane or the displacement): the probe itself, the probe's path on 4D sheets, and the
// device as a faint ghost of the probe (the gap between hand and proxy, pseudo-haptic coupling).
struct ViewFlags {
  bool probe = false;
  bool path = false;
  bool device = false;
  bool operator==(const ViewFlags&) const = default;
};

struct FrameInput {
  std::optional<ProbeMotion> probe;     // the proxy as drawn (visual and pressed position)
  // The camera drawn under the current pose (an orbit, the maze's follower), before `view`.
  std::optional<Camera> camera;
  std::optional<ViewPose> view;         // [navigation] / rolling: carries the camera and light
  std::optional<glm::dvec3> device_mm;  // the hand, drawn as a ghost when shown
  std::optional<ProbeSheet> sheet;      // each given sheet also extends the 4D path when shown
  std::optional<std::vector<glm::dvec3>> bodies_mm;  // Scene::bodies' centres, in order
  std::optional<std::vector<WorldMarker>> markers;   // charges, bands, the force arrow
  std::optional<ViewFlags> show;        // the flags from this frame on (a test's switch)
  // (Deformable surfaces are not a frame input: the session steps those of its view,
  // frame/haptic_frame.h step_deformation, and the renderer draws them as they stand.)
};

// A frame that moves only the probe (a frame at a chosen probe state: a bench, a test, the library).
FrameInput probe_frame_input(const glm::dvec3& position_mm, const glm::dvec3& velocity_mm_s);

// The scene's bodies at their start positions and its markers (charges, bands) with the scene's
// probe: how a scene looks before any haptic tick, what a fresh view holds (render/view.h make_view).
FrameInput start_frame_input(const Scene& scene);

}  // namespace ps
