// The parameter panel of `pseudoshadow run` (Dear ImGui, toggled with F1): every material
// parameter with its unit and valid range, the probe and camera values, live plots of the
// intensity curve and of the speed -> amplitude curve, the reload status, and "Save
// overrides". Edits go through TuneSession::set, i.e. exactly a --set, and apply to the next
// frame. Drawn after screenshots are taken, so it never appears in them.
//
// ImGui backends: Debian's imgui_impl_glfw.cpp and imgui_impl_opengl3.cpp, the latter built
// with IMGUI_IMPL_OPENGL_LOADER_CUSTOM on our GL pointer table (gl/gl.h) instead of its own
// dlopen("libGL") loader: one loader for the whole process. It saves and restores the GL state
// it touches, so the renderer's passes are unaffected.
#pragma once

#include <memory>
#include <string>

#include "tune/tune_session.h"

struct GLFWwindow;

namespace ps {

class TunePanel {
 public:
  // Installs ImGui's GLFW callbacks, chained to the ones already installed (window input).
  explicit TunePanel(GLFWwindow* window);
  ~TunePanel();
  TunePanel(const TunePanel&) = delete;
  TunePanel& operator=(const TunePanel&) = delete;

  void toggle() { visible_ = !visible_; }
  bool visible() const { return visible_; }
  // True while the panel has the mouse/keyboard (the probe should then ignore them).
  bool wants_input() const;

  // Builds and draws the panel into the current framebuffer; applies edits to `session`.
  void draw(TuneSession& session);

 private:
  void material_section(TuneSession& session);
  void probe_camera_section(TuneSession& session);
  void plots(const TuneSession& session);
  void apply(TuneSession& session, const std::string& key, const std::string& value);

  bool visible_ = false;
  int material_ = 0;
  std::string status_;
};

}  // namespace ps
