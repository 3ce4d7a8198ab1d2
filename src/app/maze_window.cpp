#include "app/maze_window.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <cstdio>

#include "app/session.h"
#include "devices/glfw_input.h"
#include "devices/sample_log.h"
#include "gl/context.h"
#include "render/present.h"
#include "render/renderer.h"

namespace ps {

namespace {

constexpr double kScoreSeconds = 5.0;  // how long a pass's score screen stays up
constexpr double kMmPerCount = 0.15;   // captured mouse: mm on the floor per raw count

struct Window {  // context first: the renderer's GL objects die before it
  std::unique_ptr<gl::Context> ctx;
  std::unique_ptr<Renderer> renderer;
  std::unique_ptr<Device> device;
  GlfwInputDevice* mouse = nullptr;
};

// The floor under the camera target: the plane the captured mouse moves the probe over.
PlaneAxes floor_plane(const Renderer& r) {
  return {r.scene().camera.target, glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)};
}

Status open_window(const maze::SessionOptions& o, const std::string& device, const maze::SessionCore& core, Window& w) {
  gl::ContextDesc desc;
  desc.backend = gl::Backend::kGlfw;
  desc.window_width = desc.window_height = o.desc.image_size;
  desc.window_title = "pseudoshadow maze - " + o.info.participant;
  auto ctx = gl::create_context(desc);
  if (!ctx) return ctx.error();
  w.ctx = std::move(ctx.value());
  auto r = Renderer::create(core.scene().scene, RendererOptions{});
  if (!r) return r.error();
  w.renderer = std::move(r.value());
  if (device.empty() || device == "mouse") {
    GlfwInputParams params;
    params.mm_per_count = kMmPerCount;
    auto m = std::make_unique<GlfwInputDevice>(GlfwInputDevice::Kind::kMouse, w.ctx->window(), params);
    m->toggle_capture();  // relative: the camera follows the probe, so an absolute pointer would chase it
    w.mouse = m.get();
    w.device = std::move(m);
    return ok_status();
  }
  auto d = open_device_log(device);
  if (!d) return make_error("--device: " + d.error().message);
  if (d->pointer) return make_error("--device: pointer logs are not supported by the maze; use mouse, trajectory: or playback:");
  w.device = std::move(d->device);
  return ok_status();
}

void text_window(const char* id, ImVec2 pos, const std::string& text, float scale) {
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowBgAlpha(0.75f);
  ImGui::Begin(id, nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs);
  ImGui::SetWindowFontScale(scale);
  ImGui::TextUnformatted(text.c_str());
  ImGui::End();
}

std::string score_text(const maze::PassScore& s, bool cues) {
  std::string t = "Pass " + std::to_string(s.pass + 1) + ": " + std::to_string(s.correct()) + " of 6 rooms right\n";
  for (const maze::Trial& r : s.trials)
    t += "\nroom " + std::to_string(r.index + 1) + (cues ? "" : std::string("  ") + maze::cue_label(r.cue)) + "  " +
         maze::exit_name(r.chosen) + "  " + (r.ok ? "RIGHT" : "WRONG");
  return t;
}

}  // namespace

int run_maze_window(const cli::Command& cmd, const maze::SessionOptions& o, const std::string& device) {
  auto opened = maze::SessionCore::open(o);
  if (!opened) return cmd.fail(opened.error());
  maze::SessionCore& core = *opened.value();
  Window w;
  if (Status s = open_window(o, device, core, w); !s) return cmd.fail(s.error());
  GLFWwindow* win = w.ctx->window();
  SteadyClock clock;
  HapticLoop loop(*w.device, clock, o.haptics, core.haptic().get());
  SampleRecorder recorder(o.record_path);
  loop.set_recorder(&recorder);
  if (w.mouse) w.mouse->poll(0.0, pointer_view(*w.renderer, floor_plane(*w.renderer)));
  loop.start();
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;
  ImGui_ImplGlfw_InitForOpenGL(win, true);
  ImGui_ImplOpenGL3_Init("#version 450 core");
  std::string score, reason = "quit";
  Result<maze::SessionResult> result = make_error("the session did not end");
  double score_until = -1.0, last_flush = 0.0, end_at = -1.0;
  HapticState st;
  Status failed = ok_status();
  auto on_score = [&](const maze::PassScore& s) -> Status {
    score = score_text(s, o.info.cues);
    score_until = st.time_s + kScoreSeconds;
    return ok_status();
  };
  while (!glfwWindowShouldClose(win) && glfwGetKey(win, GLFW_KEY_ESCAPE) != GLFW_PRESS) {
    glfwPollEvents();
    st = loop.state().read();
    if (w.mouse) w.mouse->poll(st.time_s, pointer_view(*w.renderer, floor_plane(*w.renderer)));
    if (!core.finished())
      if (failed = core.step(st, loop, on_score); !failed) break;
    if (core.finished() && end_at < 0.0) {  // logged now (the session's time), then the last score shows
      end_at = st.time_s + kScoreSeconds;
      result = core.finish(st.time_s, reason);
    }
    if (end_at >= 0.0 && st.time_s > end_at) break;
    if (w.device->duration_s() >= 0.0 && st.time_s > w.device->duration_s() && end_at < 0.0) {
      reason = "device_ended";
      break;
    }
    if (core.take_scene_changed()) {
      auto r = Renderer::create(core.scene().scene, RendererOptions{});
      if (!r) return cmd.fail(r.error());
      w.renderer = std::move(r.value());
    }
    if (st.have_sample) {
      w.renderer->set_camera(maze::follow_camera(o.desc, st.proxy_mm));
      w.renderer->set_probe_state(st.proxy_mm, st.velocity_mm_s);
    }
    if (failed = w.renderer->render_frame(); !failed) break;
    int fw = 0, fh = 0;
    glfwGetFramebufferSize(win, &fw, &fh);
    present_to_default_framebuffer(*w.renderer, fw, fh);
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    if (const std::string label = core.label(); !label.empty()) text_window("##label", ImVec2(10, 10), label, 2.0f);
    if (st.time_s < score_until) text_window("##score", ImVec2(40, 80), score, 1.6f);
    if (core.finished()) text_window("##done", ImVec2(40, fh - 60.0f), "All rooms right: the session is over.", 1.6f);
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    glfwSwapBuffers(win);
    if (st.time_s - last_flush >= 1.0) {
      last_flush = st.time_s;
      if (Status s = recorder.flush(); !s) std::fprintf(stderr, "pseudoshadow maze: %s\n", s.error().message.c_str());
    }
  }
  loop.stop();
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  if (end_at < 0.0) result = core.finish(st.time_s, reason);  // quit or device ended before the criterion
  if (Status s = recorder.close(); !s) return cmd.fail(s.error());
  if (!failed) return cmd.fail(failed.error());
  if (!result) return cmd.fail(result.error());
  std::printf("maze: %s after %d pass%s (%s), %.1f s; log %s\n", o.info.participant.c_str(), result->passes,
              result->passes == 1 ? "" : "es", result->reason.c_str(), result->time_s, o.log_path.c_str());
  return cli::kExitOk;
}

}  // namespace ps
