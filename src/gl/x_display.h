// The X display under a GLFW window (src/gl/x_display.cpp), kept apart from the rest of the GL
// layer: Xlib's headers define macros (Status, None, Bool, ...) that clash with the project's names.
#pragma once

namespace ps::gl::detail {

// After glfwInit and the window: Xlib's I/O error and exit handlers only note that the display
// went away (gl::display_lost) instead of exiting the process.
void watch_x_display();

}  // namespace ps::gl::detail
