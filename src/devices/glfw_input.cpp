#include "devices/glfw_input.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>

namespace ps {

GlfwInputDevice::GlfwInputDevice(Kind kind, GLFWwindow* window, const GlfwInputParams& params)
    : kind_(kind), window_(window), params_(params), height_(params.height) {}

GlfwInputDevice::~GlfwInputDevice() = default;

void GlfwInputDevice::toggle_capture() {
  captured_ = !captured_;
  have_cursor_ = false;  // the disabled cursor's virtual position is a new origin: no jump
  glfwSetInputMode(window_, GLFW_CURSOR, captured_ ? GLFW_CURSOR_DISABLED : GLFW_CURSOR_NORMAL);
  // Raw motion only exists while the cursor is disabled; not every platform has it.
  if (glfwRawMouseMotionSupported())
    glfwSetInputMode(window_, GLFW_RAW_MOUSE_MOTION, captured_ ? GLFW_TRUE : GLFW_FALSE);
}

void GlfwInputDevice::poll(double now_s, const PointerView& view) {
  DeviceSample s;
  s.time_s = now_s;
  s.placements = placements_;
  if (kind_ == Kind::kMouse) {
    s.position_mm = poll_mouse(view);
    for (int b = 0; b < 3; ++b)
      if (glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_1 + b) == GLFW_PRESS) s.buttons |= 1u << b;
    s.valid = true;
  } else {
    s.valid = poll_gamepad(now_s, view, s);  // false: no gamepad connected
  }
  latest_.publish(next_stroke(latest_.read(), s, now_s, last_poll_s_, kMaxStrokeS));  // its own last publish
  last_poll_s_ = now_s;
}

DeviceSample GlfwInputDevice::read(double now_s) {
  return latest_.read().read(now_s);
}

void GlfwInputDevice::snap() {
  PollStroke k = latest_.read();
  k.snap();
  latest_.publish(k);
}

glm::dvec3 GlfwInputDevice::poll_mouse(const PointerView& view) {
  glm::dvec2 cursor;
  glfwGetCursorPos(window_, &cursor.x, &cursor.y);
  if (!have_cursor_) {
    last_cursor_ = cursor;
    if (!cursor_moved_) first_cursor_ = cursor;
    have_cursor_ = true;
  }
  const glm::dvec2 counts = cursor - last_cursor_;
  last_cursor_ = cursor;
  if (captured_) return map_.relative(view, counts, params_.mm_per_count, height_.mm());
  cursor_moved_ = cursor_moved_ || cursor != first_cursor_;
  const glm::dvec2 pointer = cursor_moved_ ? cursor : 0.5 * view.window_size;
  return map_.absolute(view, pointer, height_.mm());
}

bool GlfwInputDevice::poll_gamepad(double now_s, const PointerView& view, DeviceSample& s) {
  GLFWgamepadstate st{};
  int jid = -1;
  for (int j = GLFW_JOYSTICK_1; j <= GLFW_JOYSTICK_LAST && jid < 0; ++j)
    if (glfwJoystickIsGamepad(j) && glfwGetGamepadState(j, &st)) jid = j;
  if (jid < 0) return false;
  const double dt = std::clamp(now_s - last_poll_s_, 0.0, 0.1);
  auto dead = [](float a) { return std::abs(a) < 0.12f ? 0.0 : static_cast<double>(a); };
  // Stick y grows downwards, like the screen's: the relative mapping's counts are in mm here.
  const glm::dvec2 move_mm = glm::dvec2(dead(st.axes[GLFW_GAMEPAD_AXIS_LEFT_X]), dead(st.axes[GLFW_GAMEPAD_AXIS_LEFT_Y])) *
                             params_.stick_speed_mm_s * dt;
  // Triggers rest at -1 and go to +1.
  const double up = 0.5 * (st.axes[GLFW_GAMEPAD_AXIS_RIGHT_TRIGGER] + 1.0);
  const double down = 0.5 * (st.axes[GLFW_GAMEPAD_AXIS_LEFT_TRIGGER] + 1.0);
  height_.add_mm((up - down) * params_.stick_speed_mm_s * 0.5 * dt);
  s.position_mm = map_.relative(view, move_mm, 1.0, height_.mm());
  for (int b = 0; b <= GLFW_GAMEPAD_BUTTON_LAST; ++b)
    if (st.buttons[b] == GLFW_PRESS) s.buttons |= 1u << b;
  return true;
}

}  // namespace ps
