// What a live program hears from its window (app/window/live_window.h): the one set of GLFW
// callbacks a LiveWindow installs calls these on the main thread, during glfwPollEvents. Each
// does nothing unless overridden: `run` hears everything (app/window/window_input.h), the maze
// its keys and the pointer's comings and goings, calibrate its arrow keys. Keys, actions and
// mods are GLFW's (GLFW_KEY_*, GLFW_PRESS / GLFW_REPEAT / GLFW_RELEASE, GLFW_MOD_*).
// No GLFW header here: the listeners' own logic is tested without a window.
#pragma once

namespace ps {

class WindowListener {
 public:
  virtual ~WindowListener() = default;
  virtual void on_key(int /*key*/, int /*action*/, int /*mods*/) {}
  // A character typed (a layout's '?', wherever the keyboard puts it).
  virtual void on_char(unsigned int /*codepoint*/) {}
  // A wheel's vertical notches; `shift`: either Shift key held.
  virtual void on_scroll(double /*dy*/, bool /*shift*/) {}
  // A mouse button pressed or released, with the cursor's position then (window coordinates).
  virtual void on_mouse_button(int /*button*/, int /*action*/, double /*x*/, double /*y*/) {}
  virtual void on_cursor(double /*x*/, double /*y*/) {}
  virtual void on_enter(bool /*entered*/) {}
  virtual void on_focus(bool /*focused*/) {}
};

}  // namespace ps
