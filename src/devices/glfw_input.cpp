#include "devices/glfw_input.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>

namespace ps {

GlfwInputDevice::GlfwInputDevice(Kind kind, GLFWwindow* window, const GlfwInputParams& params)
    : kind_(kind), window_(window), params_(params), height_mm_(params.start_height_mm) {}

GlfwInputDevice::~GlfwInputDevice() = default;

void GlfwInputDevice::toggle_capture() {
  captured_ = !captured_;
  glfwSetInputMode(window_, GLFW_CURSOR, captured_ ? GLFW_CURSOR_DISABLED : GLFW_CURSOR_NORMAL);
  // Raw motion only exists while the cursor is disabled; not every platform has it.
  if (glfwRawMouseMotionSupported())
    glfwSetInputMode(window_, GLFW_RAW_MOUSE_MOTION, captured_ ? GLFW_TRUE : GLFW_FALSE);
}

void GlfwInputDevice::poll(double now_s, const PlaneAxes& axes) {
  if (kind_ == Kind::kMouse) poll_mouse(now_s, axes);
  else poll_gamepad(now_s, axes);
  last_poll_s_ = now_s;
}

void GlfwInputDevice::poll_mouse(double now_s, const PlaneAxes& axes) {
  double cx = 0.0, cy = 0.0;
  int w = 0, h = 0;
  glfwGetCursorPos(window_, &cx, &cy);
  glfwGetWindowSize(window_, &w, &h);
  if (glfwGetKey(window_, GLFW_KEY_PAGE_UP) == GLFW_PRESS) height_mm_ += params_.scroll_step_mm * 0.25;
  if (glfwGetKey(window_, GLFW_KEY_PAGE_DOWN) == GLFW_PRESS) height_mm_ -= params_.scroll_step_mm * 0.25;
  const double u = (cx - 0.5 * w) * params_.mm_per_pixel;
  const double v = (0.5 * h - cy) * params_.mm_per_pixel;  // screen y grows downwards
  DeviceSample s;
  s.time_s = now_s;
  s.position_mm = axes.origin + u * axes.t + v * axes.b + height_mm_ * axes.n;
  for (int b = 0; b < 3; ++b)
    if (glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_1 + b) == GLFW_PRESS) s.buttons |= 1u << b;
  s.valid = true;
  latest_.publish(s);
}

void GlfwInputDevice::poll_gamepad(double now_s, const PlaneAxes& axes) {
  GLFWgamepadstate st{};
  int jid = -1;
  for (int j = GLFW_JOYSTICK_1; j <= GLFW_JOYSTICK_LAST && jid < 0; ++j)
    if (glfwJoystickIsGamepad(j) && glfwGetGamepadState(j, &st)) jid = j;
  DeviceSample s;
  s.time_s = now_s;
  if (jid < 0) { latest_.publish(s); return; }  // valid = false: no gamepad connected
  const double dt = std::clamp(now_s - last_poll_s_, 0.0, 0.1);
  auto dead = [](float a) { return std::abs(a) < 0.12f ? 0.0 : static_cast<double>(a); };
  stick_pos_mm_.x += dead(st.axes[GLFW_GAMEPAD_AXIS_LEFT_X]) * params_.stick_speed_mm_s * dt;
  stick_pos_mm_.y -= dead(st.axes[GLFW_GAMEPAD_AXIS_LEFT_Y]) * params_.stick_speed_mm_s * dt;
  // Triggers rest at -1 and go to +1.
  const double up = 0.5 * (st.axes[GLFW_GAMEPAD_AXIS_RIGHT_TRIGGER] + 1.0);
  const double down = 0.5 * (st.axes[GLFW_GAMEPAD_AXIS_LEFT_TRIGGER] + 1.0);
  height_mm_ += (up - down) * params_.stick_speed_mm_s * 0.5 * dt;
  s.position_mm = axes.origin + stick_pos_mm_.x * axes.t + stick_pos_mm_.y * axes.b + height_mm_ * axes.n;
  for (int b = 0; b <= GLFW_GAMEPAD_BUTTON_LAST; ++b)
    if (st.buttons[b] == GLFW_PRESS) s.buttons |= 1u << b;
  s.valid = true;
  latest_.publish(s);
}

}  // namespace ps
