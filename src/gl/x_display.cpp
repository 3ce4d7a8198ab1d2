// The X server went away (killed, a remote session dropped): Xlib calls its I/O error handler,
// then its exit handler, whose default exit()s the process on the spot, with every log still
// open. Here both only note it and return: Xlib then marks the connection dead and every later
// call on it returns at once, and the command's loop ends the session as a stop signal does
// (app/cli/stop_signal.h), flushing its logs (docs/hardening.md, "Faults").
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#define GLFW_EXPOSE_NATIVE_X11
#include <GLFW/glfw3native.h>
#include <X11/Xlib.h>

#include <atomic>

#include "gl/x_display.h"

namespace ps::gl {
namespace {

std::atomic<bool> g_display_lost{false};

int on_x_io_error(Display*) {
  g_display_lost.store(true, std::memory_order_relaxed);
  return 0;  // then the exit handler below
}

void on_x_io_exit(Display*, void*) { g_display_lost.store(true, std::memory_order_relaxed); }

}  // namespace

// Declared in gl/context.h (it has no Xlib).
bool display_lost() { return g_display_lost.load(std::memory_order_relaxed); }

namespace detail {

void watch_x_display() {
  Display* dpy = glfwGetX11Display();
  if (dpy == nullptr) return;
  XSetIOErrorHandler(on_x_io_error);
  XSetIOErrorExitHandler(dpy, on_x_io_exit, nullptr);
}

}  // namespace detail
}  // namespace ps::gl
