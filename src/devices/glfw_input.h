// Mouse+keyboard and gamepad through GLFW. GLFW input may only be polled on the main thread,
// so poll() runs there once per frame and publishes a DeviceSample through a single-writer
// Snapshot; read() on the haptic thread returns the newest one (sample-and-hold).
//   mouse:   cursor x/y move the probe on the reference plane (mm_per_pixel around the
//            plane origin), scroll or PageUp/PageDown change the height along the normal;
//            buttons = mouse buttons. Key M captures the cursor, which enables raw (unscaled,
//            unaccelerated) motion where GLFW supports it.
//   gamepad: left stick moves on the plane at stick_speed_mm_s, triggers raise/lower, buttons
//            = gamepad buttons (first connected joystick with a gamepad mapping).
#pragma once

#include <memory>
#include <string>

#include "core/result.h"
#include "core/snapshot.h"
#include "devices/device.h"

struct GLFWwindow;

namespace ps {

struct PlaneAxes {  // where the device moves: origin and orthonormal tangents/normal (mm)
  glm::dvec3 origin{0.0}, t{1.0, 0.0, 0.0}, b{0.0, 1.0, 0.0}, n{0.0, 0.0, 1.0};
};

struct GlfwInputParams {
  double mm_per_pixel = 0.25;
  double scroll_step_mm = 1.0;
  double stick_speed_mm_s = 80.0;
  double start_height_mm = 20.0;
};

class GlfwInputDevice final : public Device {
 public:
  enum class Kind { kMouse, kGamepad };
  GlfwInputDevice(Kind kind, GLFWwindow* window, const GlfwInputParams& params);
  ~GlfwInputDevice() override;
  // Main thread, once per frame: polls GLFW state (after glfwPollEvents) and publishes.
  void poll(double now_s, const PlaneAxes& axes);
  DeviceSample read(double now_s) override { return latest_.read(); }
  std::string name() const override { return kind_ == Kind::kMouse ? "mouse" : "gamepad"; }
  void add_scroll(double dy) { height_mm_ += dy * params_.scroll_step_mm; }
  void toggle_capture();

 private:
  void poll_mouse(double now_s, const PlaneAxes& axes);
  void poll_gamepad(double now_s, const PlaneAxes& axes);

  Kind kind_;
  GLFWwindow* window_;
  GlfwInputParams params_;
  double height_mm_, last_poll_s_ = 0.0;
  glm::dvec2 stick_pos_mm_{0.0};
  bool captured_ = false;
  Snapshot<DeviceSample> latest_;
};

}  // namespace ps
