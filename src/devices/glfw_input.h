// Mouse+keyboard and gamepad through GLFW. GLFW input may only be polled on the main thread,
// so poll() runs there once per frame and publishes its reading through a single-writer Snapshot;
// read() on the haptic thread gives the hand on its way from the last reading to the newest one
// (devices/poll_stroke.h: one frame behind, never past a reading).
//   mouse:   the probe is where the pointer is (PointerMap's absolute mapping through the
//            current camera, devices/pointer_map.h): its shadow's centre sits under the pointer.
//            Until the pointer first moves, the window centre stands in for it (a pointer
//            outside a fresh window must not put the probe in a corner). Key M captures the
//            cursor: raw relative motion (unaccelerated where GLFW supports it) then moves the
//            probe by mm_per_count per count, screen-aligned; M again returns it under the
//            pointer. The height comes from a HeightControl (scroll, stepping keys:
//            add_scroll / add_height_steps); buttons = mouse buttons.
//   gamepad: left stick moves on the plane at stick_speed_mm_s (screen-aligned), right/left
//            trigger raise/lower at stick_speed_mm_s / 2, buttons = gamepad buttons (first
//            connected joystick with a gamepad mapping).
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "core/result.h"
#include "core/snapshot.h"
#include "devices/device.h"
#include "devices/pointer_map.h"
#include "devices/poll_stroke.h"

struct GLFWwindow;

namespace ps {

struct GlfwInputParams {
  // Captured pointer: mm on the plane per raw count. 0.1 mm is about one screen pixel of the
  // default scene at its default zoom (~0.084 mm per pixel at the plank), so the feel matches
  // the absolute mapping's.
  double mm_per_count = 0.1;
  double stick_speed_mm_s = 80.0;
  HeightParams height;
};

class GlfwInputDevice final : public Device {
 public:
  enum class Kind { kMouse, kGamepad };
  GlfwInputDevice(Kind kind, GLFWwindow* window, const GlfwInputParams& params);
  ~GlfwInputDevice() override;
  // Main thread, once per frame: polls GLFW state (after glfwPollEvents), maps it with the
  // current view (camera, window, plane) and publishes.
  void poll(double now_s, const PointerView& view);
  // Haptic thread: the hand at now_s on its way to the newest reading (time_s = now_s,
  // devices/poll_stroke.h; docs/window.md, "Between two frames").
  DeviceSample read(double now_s) override;
  // Any thread: the newest poll's reading, where the hand is heading (time_s: the poll's time).
  DeviceSample newest() const { return latest_.read().to; }
  // Main thread, after a poll: the hand is at the newest reading from now on, no way between (the
  // haptic loop is told to place it there: HapticLoop::place_hand).
  void snap();
  // The longest way between two readings, s: a slower frame's hand waits at the reading for the
  // rest of it (10 frames a second and fewer), so the hand lags the pointer by at most this.
  static constexpr double kMaxStrokeS = 0.1;
  std::string name() const override { return kind_ == Kind::kMouse ? "mouse" : "gamepad"; }
  Kind kind() const { return kind_; }
  void add_scroll(double notches) { height_.scroll(notches); }
  void add_height_steps(int presses) { height_.step(presses); }
  double height_mm() const { return height_.mm(); }
  // Back to the hover height a session starts at (after a scene switch: the new scene is not
  // pressed into by a press made in the old one).
  void reset_height() { height_.set(params_.height.start_mm); }
  // Main thread: how deep the scene needs the hand to go (HeightControl::reach_depth).
  void reach_depth(double depth_mm) { height_.reach_depth(depth_mm); }
  void toggle_capture();
  // Main thread. The cursor's present position becomes the relative origin at the next poll:
  // called when GLFW may have moved its virtual cursor by something other than the person's
  // motion (the pointer entering the window, focus returning, the cursor being grabbed), so
  // that jump never reaches the probe.
  void rebase() { have_cursor_ = false; }
  // Main thread: the probe's point on the plane (its shadow's centre) is `hit_mm` from the next
  // poll on: where the hand starts, or where a clutch puts it back under the proxy.
  // Counted in the samples from that poll on (DeviceSample::placements).
  void place(const glm::dvec3& hit_mm) {
    map_.set_hit(hit_mm);
    ++placements_;
  }
  // The last poll's jump of the point under the pointer across a silhouette (PointerMap).
  double parallax_jump_mm() const { return map_.parallax_jump_mm(); }

 private:
  glm::dvec3 poll_mouse(const PointerView& view);
  bool poll_gamepad(double now_s, const PointerView& view, DeviceSample& s);

  Kind kind_;
  GLFWwindow* window_;
  GlfwInputParams params_;
  HeightControl height_;
  PointerMap map_;
  double last_poll_s_ = 0.0;
  glm::dvec2 first_cursor_{0.0}, last_cursor_{0.0};
  bool have_cursor_ = false, cursor_moved_ = false, captured_ = false;
  std::uint32_t placements_ = 0;
  Snapshot<PollStroke> latest_;
};

}  // namespace ps
