// `pseudoshadow doctor`: what a newcomer runs when something does not work. One line per thing
// the program relies on (the shared data, each GL backend, the display and a window, audio,
// gamepads and rumble, real-time scheduling, versions): ok / missing / note, and how to fix it.
// Exit 0 when the headless path works (the shared data and at least one headless GL backend),
// since that is what `render`, `replay` and the test suite need; 1 otherwise.
#include <sys/syscall.h>
#include <unistd.h>

#include <pthread.h>
#include <sched.h>

#include <GLFW/glfw3.h>
#include <SDL2/SDL.h>
#include <glslang/build_info.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "app/cli/cli.h"
#include "app/commands.h"
#include "audio/live_audio.h"
#include "core/install_layout.h"
#include "gl/context.h"
#include "gl/egl_device.h"
#include "haptics/rtkit.h"
#include "vibration/rumble.h"

namespace ps {
namespace {

enum class Verdict { kOk, kMissing, kNote };

// One line of the report: what was checked, the verdict, what was found and, when not ok, the fix.
struct Finding {
  std::string what;
  Verdict verdict = Verdict::kOk;
  std::string found;
  std::string fix;
};

const char* verdict_word(Verdict v) {
  switch (v) {
    case Verdict::kOk: return "ok";
    case Verdict::kMissing: return "missing";
    case Verdict::kNote: return "note";
  }
  return "?";
}

Finding check_data() {
  namespace fs = std::filesystem;
  const fs::path dir = install::data_dir();
  std::string absent;
  for (const char* sub : {"glsl/surface.frag", "scenes/default.toml", "textures"})
    if (!fs::exists(dir / sub)) absent += std::string(absent.empty() ? "" : ", ") + sub;
  if (absent.empty()) return {"shared data", Verdict::kOk, dir.string(), ""};
  return {"shared data", Verdict::kMissing, dir.string() + " lacks " + absent,
          "build with tools/bootstrap.sh, or install (cmake --install build) so share/pseudoshadow sits next to bin/"};
}

// A headless backend: a 4.5 core context, its renderer and version.
Finding check_backend(gl::Backend backend, const std::string& fix) {
  gl::ContextDesc desc;
  desc.backend = backend;
  const std::string what = backend == gl::Backend::kEgl ? "EGL" : "OSMesa";
  auto ctx = gl::create_context(desc);
  if (!ctx) return {what, Verdict::kMissing, ctx.error().message, fix};
  std::string found = (*ctx)->renderer() + ", OpenGL " + (*ctx)->version();
  if (backend == gl::Backend::kEgl) found += ", display: " + (*ctx)->egl_device();
  return {what, Verdict::kOk, found, ""};
}

Finding check_egl_devices() {
  auto devices = gl::list_egl_devices();
  if (!devices) return {"EGL devices", Verdict::kNote, devices.error().message, "--gpu N needs EGL_EXT_device_enumeration"};
  int hardware = 0;
  for (const gl::EglDeviceInfo& d : *devices) hardware += d.software ? 0 : 1;
  std::string found = std::to_string(devices->size()) + " (" + std::to_string(hardware) + " hardware)";
  for (const gl::EglDeviceInfo& d : *devices) found += "; " + std::to_string(d.index) + ": " + d.name;
  if (hardware > 0) return {"EGL devices", Verdict::kOk, found, ""};
  return {"EGL devices", Verdict::kNote, found,
          "rendering runs on the CPU (llvmpipe); for a GPU install its driver, then pick it with --gpu auto or --gpu N"};
}

Finding check_display() {
  const char* x = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if (x != nullptr && *x != '\0') return {"display", Verdict::kOk, std::string("DISPLAY=") + x, ""};
  if (wayland != nullptr && *wayland != '\0')
    return {"display", Verdict::kNote, std::string("WAYLAND_DISPLAY=") + wayland + ", no DISPLAY",
            "the window needs X: XWayland sets DISPLAY; or run under xvfb-run -a"};
  return {"display", Verdict::kMissing, "DISPLAY is not set",
          "headless commands work; for `run`, `maze` or `calibrate` at a window log in graphically, "
          "ssh -X, or try it under: xvfb-run -a pseudoshadow run"};
}

Finding check_window(bool have_display) {
  if (!have_display) return {"window", Verdict::kMissing, "not tried (no display)", "see the display line"};
  gl::ContextDesc desc;
  desc.backend = gl::Backend::kGlfw;
  desc.visible = false;
  auto ctx = gl::create_context(desc);
  if (!ctx) return {"window", Verdict::kMissing, ctx.error().message,
                    "the X server needs GLX with OpenGL 4.5 core (Mesa: libgl1-mesa-dri); check `glxinfo -B`"};
  return {"window", Verdict::kOk, (*ctx)->renderer() + ", OpenGL " + (*ctx)->version(), ""};
}

Finding check_audio() {
  std::unique_ptr<audio::LiveAudio> player = audio::LiveAudio::open(audio::LiveAudioDesc{});
  if (player && player->active()) return {"audio output", Verdict::kOk, player->device_name(), ""};
  return {"audio output", Verdict::kNote, player ? player->warning() : "OpenAL did not start",
          "event sounds and --vibration sound are silent; a desktop session (PulseAudio/PipeWire) or ALSA device gives sound"};
}

Finding check_gamepads() {
  SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
  if (SDL_InitSubSystem(SDL_INIT_GAMECONTROLLER) != 0)
    return {"gamepads", Verdict::kNote, std::string("SDL could not start: ") + SDL_GetError(), ""};
  const int count = SDL_NumJoysticks();
  std::string found = std::to_string(count) + " joystick(s)";
  for (int i = 0; i < count; ++i) {
    const char* name = SDL_JoystickNameForIndex(i);
    found += std::string("; ") + (name != nullptr ? name : "unnamed") + (SDL_IsGameController(i) ? " (gamepad)" : "");
  }
  SDL_QuitSubSystem(SDL_INIT_GAMECONTROLLER);
  if (count > 0) return {"gamepads", Verdict::kOk, found, ""};
  return {"gamepads", Verdict::kNote, found, "`run --device gamepad` needs one plugged in (and read access to /dev/input/event*)"};
}

Finding check_rumble() {
  auto rumble = vibration::RumbleOut::open(vibration::RumbleDesc{});
  if (rumble) return {"rumble", Verdict::kOk, (*rumble)->name(), ""};
  return {"rumble", Verdict::kNote, rumble.error().message, "--vibration rumble needs a gamepad with rumble motors"};
}

// On a short-lived thread of its own, as the haptic loop asks for it: SCHED_FIFO where this
// process may, else SCHED_RR through RealtimeKit.
Finding check_realtime() {
  Finding f{"real-time", Verdict::kOk, "", ""};
  std::thread probe([&f] {
    sched_param sp{};
    sp.sched_priority = 80;
    if (pthread_setschedparam(pthread_self(), SCHED_FIFO, &sp) == 0) {
      f.found = "SCHED_FIFO allowed (CAP_SYS_NICE or RLIMIT_RTPRIO)";
      return;
    }
    const Result<int> rr = rtkit::make_thread_realtime(static_cast<pid_t>(::syscall(SYS_gettid)), sp.sched_priority);
    if (rr) {
      f.found = "SCHED_RR " + std::to_string(rr.value()) + " through RealtimeKit";
      return;
    }
    f.verdict = Verdict::kNote;
    f.found = rr.error().message;
    f.fix = "the haptic loop runs at normal priority (more jitter under load); install and start rtkit "
            "(apt-get install rtkit dbus), or grant RLIMIT_RTPRIO in /etc/security/limits.conf";
  });
  probe.join();
  return f;
}

Finding check_versions() {
  SDL_version sdl{};
  SDL_GetVersion(&sdl);
  std::string found = std::string("pseudoshadow ") + PS_VERSION + ", GLFW " + glfwGetVersionString() + ", SDL " +
                      std::to_string(sdl.major) + "." + std::to_string(sdl.minor) + "." + std::to_string(sdl.patch) +
                      ", glslang " + std::to_string(GLSLANG_VERSION_MAJOR) + "." + std::to_string(GLSLANG_VERSION_MINOR);
  return {"versions", Verdict::kOk, found, ""};
}

std::vector<Finding> examine() {
  std::vector<Finding> all;
  all.push_back(check_versions());
  all.push_back(check_data());
  all.push_back(check_backend(gl::Backend::kEgl, "install libegl1-mesa-dev libgl1-mesa-dri (tools/bootstrap.sh does)"));
  all.push_back(check_egl_devices());
  all.push_back(check_backend(gl::Backend::kOsmesa, "install libosmesa6-dev (tools/bootstrap.sh does)"));
  all.push_back(check_display());
  all.push_back(check_window(all.back().verdict == Verdict::kOk));
  all.push_back(check_audio());
  all.push_back(check_gamepads());
  all.push_back(check_rumble());
  all.push_back(check_realtime());
  return all;
}

bool headless_works(const std::vector<Finding>& all) {
  auto ok = [&](const std::string& what) {
    for (const Finding& f : all)
      if (f.what == what) return f.verdict == Verdict::kOk;
    return false;
  };
  return ok("shared data") && (ok("EGL") || ok("OSMesa"));
}

int report(const std::vector<Finding>& all) {
  for (const Finding& f : all) {
    std::printf("%-8s %-13s %s\n", verdict_word(f.verdict), f.what.c_str(), f.found.c_str());
    if (!f.fix.empty()) std::printf("%-8s %-13s fix: %s\n", "", "", f.fix.c_str());
  }
  const bool works = headless_works(all);
  std::printf("%s\n", works ? "the headless path works: `pseudoshadow render` can draw"
                            : "the headless path does not work: fix the lines marked missing above");
  return works ? cli::kExitOk : cli::kExitRuntime;
}

}  // namespace

int run_doctor(int argc, char** argv) {
  cli::Command cmd("doctor",
                   "Checks what pseudoshadow relies on, one line each: the shared data, the headless GL backends "
                   "(EGL, its devices, OSMesa), the display and a window, audio output, gamepads and rumble, "
                   "real-time scheduling and versions. Each line is ok, missing or note, with how to fix it. "
                   "Exit 0 when the headless path works (shared data and EGL or OSMesa), 1 otherwise.");
  return cmd.run(argc, argv, [] { return report(examine()); });
}

}  // namespace ps
