// The maze window's overlay and what it draws from: the events it hears, what it holds (its
// LiveWindow with the device, the renderer) and what it draws over the rendered state (the room
// label, the score, the instructions, the hand's ring). The session's loop, passes and practice
// are in app/maze/maze_window.cpp; the headless session's frames in maze/maze_frames.h.
#pragma once

#include <memory>
#include <string>

#include "app/window/live_window.h"
#include "devices/pointer_map.h"
#include "haptics/haptic_loop.h"
#include "maze/maze_session.h"
#include "render/renderer.h"

namespace ps::maze_window {

// What the window hears (app/window/live_window.h): a frame can take longer than a quick tap, so
// polled key state would lose taps.
struct Events final : WindowListener {
  bool quit = false, screenshot = false, start = false;  // start: Space or Enter (the instructions)
  int height_steps = 0;  // PageUp/Up +1, PageDown/Down -1 (0.5 mm each, HeightControl); repeats count
  // GLFW moved its virtual cursor without the person moving the mouse (the pointer entered the
  // window, focus came back and the cursor was grabbed again): the next poll rebases on it.
  bool rebase = false;
  void on_key(int key, int action, int mods) override;
  void on_enter(bool /*entered*/) override { rebase = true; }
  void on_focus(bool /*focused*/) override { rebase = true; }
};

struct Window {  // `live` before `renderer`: the renderer's GL objects die before the context
  Events events;  // heard by the window: it outlives it
  std::unique_ptr<LiveWindow> live;
  std::unique_ptr<Renderer> renderer;
  std::string out_dir;
  int screenshots = 0;
  GlfwInputDevice* input() const { return live->input(); }  // the mouse or gamepad; none for a log
};

// The floor under the camera target: the plane the captured mouse moves the probe over.
PlaneAxes floor_plane(const Renderer& r);

// `p` dropped onto `plane` along its normal.
glm::dvec3 on_plane(const PlaneAxes& plane, const glm::dvec3& p);

// What the window shows over the frame: the label (cues off), the last score for a while.
struct Overlay {
  std::string label, score, instructions;
  double score_until = -1.0;
  bool done = false, show_hand = false;
};

// A pass's score screen: each room's cue (with cues off) and exit, right or wrong.
std::string score_text(const maze::PassScore& s, bool cues);

// Renders the state, stamps a screenshot if asked (the frame plus the label, as headless
// frames have it), blits, draws the overlay.
Status draw(Window& w, const maze::MazeDesc& desc, const HapticState& st, const Overlay& ov, bool screenshot);

}  // namespace ps::maze_window
