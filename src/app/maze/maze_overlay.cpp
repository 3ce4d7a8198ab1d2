#include "app/maze/maze_overlay.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <cstdio>

#include "app/session/session.h"
#include "frame/haptic_frame.h"
#include "maze/maze_screen.h"
#include "render/present.h"

namespace ps::maze_window {

namespace {

// A faint ring where the hand is, once a wall holds the probe away from it: the participant sees
// how far the hand has run on (the clutch brings it back past MazeWindowParams::clutch_mm).
void draw_hand(const Window& w, const HapticState& st) {
  const PlaneAxes plane = floor_plane(*w.renderer);
  const glm::dvec3 hand = on_plane(plane, st.device_mm);
  if (glm::length(hand - on_plane(plane, st.proxy_mm)) < 0.5) return;  // under the probe: nothing to show
  const PointerView view = pointer_view(*w.renderer, plane, glm::dvec2(w.live->window_size()));
  const glm::dvec2 c = project_to_window(view, hand);
  const double r = glm::length(project_to_window(view, hand + view.probe_radius_mm * plane.t) - c);
  ImGui::GetBackgroundDrawList()->AddCircle(ImVec2(static_cast<float>(c.x), static_cast<float>(c.y)),
                                            static_cast<float>(r), IM_COL32(255, 255, 255, 90), 32, 2.0f);
}

}  // namespace

void Events::on_key(int key, int action, int /*mods*/) {
  if (action == GLFW_RELEASE) return;
  if (key == GLFW_KEY_PAGE_UP || key == GLFW_KEY_UP) ++height_steps;
  if (key == GLFW_KEY_PAGE_DOWN || key == GLFW_KEY_DOWN) --height_steps;
  if (action != GLFW_PRESS) return;  // a held S or Esc acts once
  if (key == GLFW_KEY_S) screenshot = true;
  if (key == GLFW_KEY_ESCAPE || key == GLFW_KEY_Q) quit = true;
  if (key == GLFW_KEY_SPACE || key == GLFW_KEY_ENTER || key == GLFW_KEY_KP_ENTER) start = true;
}

// The floor under the camera target: the plane the captured mouse moves the probe over.
PlaneAxes floor_plane(const Renderer& r) {
  return {r.camera().target, glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)};
}


glm::dvec3 on_plane(const PlaneAxes& plane, const glm::dvec3& p) { return p - glm::dot(p - plane.origin, plane.n) * plane.n; }

std::string score_text(const maze::PassScore& s, bool cues) {
  std::string t = "Pass " + std::to_string(s.pass + 1) + ": " + std::to_string(s.correct()) + " of 6 rooms right\n";
  for (const maze::Trial& r : s.trials)
    t += "\nroom " + std::to_string(r.index + 1) + (cues ? "" : std::string("  ") + maze::cue_label(r.cue)) + "  " +
         maze::exit_name(r.chosen) + "  " + (r.ok ? "RIGHT" : "WRONG");
  return t;
}

// Renders the state, stamps a screenshot if asked (the frame plus the label, as headless
// frames have it), blits, draws the overlay. The frame input is run's (haptic_frame_input) with
// the follow camera; not drive_frame, which reads the loop's newest state and publishes the
// frame's plane back to it: this frame draws the state the window's input and tracker just
// used, the waiting screens draw with no loop running, and the maze's loop collides with its
// haptic scene, taking nothing back from a frame.
Status draw(Window& w, const maze::MazeDesc& desc, const HapticState& st, const Overlay& ov, bool screenshot) {
  const HapticFrameSources maze{.camera = maze::follow_camera(desc, st.proxy_mm)};
  if (auto f = w.renderer->render(haptic_frame_input(*w.renderer, st, maze)); !f) return f.error();
  if (screenshot) {
    Image im = w.renderer->read_color();
    maze::stamp_label(im, ov.label);
    char name[48];
    std::snprintf(name, sizeof name, "/screenshot_%04d.png", w.screenshots++);
    if (Status s = write_image(w.out_dir + name, im); !s) return s;
  }
  const glm::ivec2 fb = w.live->framebuffer_size();
  present_to_default_framebuffer(*w.renderer, fb.x, fb.y);
  w.live->begin_frame();
  if (ov.show_hand && st.have_sample) draw_hand(w, st);
  if (!ov.instructions.empty()) draw_text_box("##instructions", ImVec2(30, 60), ov.instructions, 1.3f);
  if (!ov.label.empty()) draw_text_box("##label", ImVec2(10, 10), ov.label, 2.0f);
  if (st.time_s < ov.score_until) draw_text_box("##score", ImVec2(40, 80), ov.score, 1.6f);
  if (ov.done) draw_text_box("##done", ImVec2(40, static_cast<float>(fb.y) - 60.0f), "The session is over.", 1.6f);
  w.live->end_frame();
  return ok_status();
}

}  // namespace ps::maze_window
