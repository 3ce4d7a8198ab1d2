#include "app/cli/cli_groups.h"

#include <algorithm>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <unistd.h>

#include "app/cli/cli.h"
#include "gl/egl_device.h"
#include "haptics/haptic_loop.h"
#include "haptics/live_heap.h"
#include "scene/scene_io.h"
#include "tune/overrides_file.h"

namespace ps::cli {

std::vector<std::string> SceneArgs::lines() const {
  std::vector<std::string> out;
  out.reserve(overrides.size());
  for (const Override& o : overrides) out.push_back(o.text);
  return out;
}

void add_scene_options(CLI::App& app, SceneArgs& scene) {
  app.add_option("--scene", scene.path,
                 "scene file (TOML, docs/scene-format.md); default: the built-in default scene "
                 "(scenes/default.toml)")
      ->type_name("FILE")
      ->group(kSceneGroup);
  add_ordered(app, "--set", "KEY=VALUE",
              "override any scene value by its path, e.g. --set materials.wood.lambda_min=0.4 "
              "--set render.displacement=exact_max (repeatable; VALUE is a TOML value: 0.4, [0,0,5], "
              "exact_max, \"text\")",
              [&scene](const std::string& v) { scene.add(v, "--set"); })
      ->group(kSceneGroup);
  add_ordered(app, "--overrides", "FILE",
              "apply an override file (KEY = VALUE lines, as saved by `run` or `tune`, docs/tuning.md) "
              "where it stands among the --set options: later values win (repeatable)",
              [&scene](const std::string& path) {
                auto lines = read_overrides(path);
                if (!lines) throw UsageError("--overrides: " + lines.error().message);
                for (std::string& l : lines.value()) scene.add(std::move(l), "--overrides " + path);
              })
      ->group(kSceneGroup);
  app.add_option("--allow-path", scene.allow_paths,
                 "let the scene read files in DIR too (repeatable). A scene may read only files in its "
                 "own folder tree and the shipped data, so that a scene from someone else cannot read "
                 "your other files (docs/scene-format.md, \"Files a scene may read\")")
      ->type_name("DIR")
      ->group(kSceneGroup);
}

void add_probe_options(CLI::App& app, SceneArgs& scene) {
  add_ordered(app, "--probe", "X,Y,Z", "probe position in mm (sets probe.position)",
              [&scene](const std::string& v) {
                scene.add("probe.position=" + override_value(parse_vec3("--probe", v, "0,0,10")), "--probe");
              })
      ->group(kSceneGroup);
  add_ordered(app, "--velocity", "VX,VY,VZ",
              "probe velocity in mm/s (sets probe.velocity); drives the texture amplitude",
              [&scene](const std::string& v) {
                scene.add("probe.velocity=" + override_value(parse_vec3("--velocity", v, "120,0,0")),
                          "--velocity");
              })
      ->group(kSceneGroup);
}

void add_image_options(CLI::App& app, SceneArgs& scene) {
  add_ordered(app, "--size", "WxH",
              "image size in pixels, or N for NxN (sets render.size; max " + std::to_string(kMaxSide) +
                  " per side, " + std::to_string(kMaxPixels) + " pixels)",
              [&scene](const std::string& v) {
                const glm::ivec2 sz = parse_size(v, kMaxSide, kMaxPixels);
                scene.add("render.size=[" + std::to_string(sz.x) + "," + std::to_string(sz.y) + "]", "--size");
              })
      ->group(kSceneGroup);
}

std::vector<std::string> GlArgs::argv() const {
  std::vector<std::string> out = {"--backend", gl::backend_name(backend)};
  switch (gpu.kind) {
    case gl::GpuChoice::Kind::kAuto: out.insert(out.end(), {"--gpu", "auto"}); break;
    case gl::GpuChoice::Kind::kSoftware: out.insert(out.end(), {"--gpu", "software"}); break;
    case gl::GpuChoice::Kind::kIndex: out.insert(out.end(), {"--gpu", std::to_string(gpu.index)}); break;
    case gl::GpuChoice::Kind::kDefault:
    case gl::GpuChoice::Kind::kList: break;
  }
  return out;
}

namespace {

// --gpu list: runs as the option is read, so nothing else (scene, outputs) is done.
[[noreturn]] void list_devices_and_exit() {
  auto devices = gl::list_egl_devices();
  if (!devices) throw RuntimeFailure("--gpu list: " + devices.error().message);
  std::fputs("index  name  kind  render node\n", stdout);
  std::fputs(gl::format_egl_devices(devices.value()).c_str(), stdout);
  throw CLI::Success();
}

}  // namespace

void add_gl_options(CLI::App& app, GlArgs& args) {
  app.add_option_function<std::string>(
         "--backend",
         [&args](const std::string& v) {
           auto b = gl::parse_backend(v);
           if (!b || b.value() == gl::Backend::kGlfw)
             throw UsageError("--backend: '" + v + "' is not a headless backend (give auto, egl or osmesa)");
           args.backend = b.value();
         },
         "auto (EGL, then OSMesa) | egl | osmesa")
      ->type_name("B")
      ->group(kGlGroup);
  app.add_option_function<std::string>(
         "--gpu",
         [&args](const std::string& v) {
           auto g = gl::parse_gpu(v);
           if (!g) throw UsageError("--gpu: " + g.error().message);
           if (g->kind == gl::GpuChoice::Kind::kList) list_devices_and_exit();
           args.gpu = g.value();
         },
         "the EGL display: auto (a hardware EGL device, else Mesa's surfaceless platform, else OSMesa; says "
         "which), list (print the EGL devices and exit), software (Mesa's software device) or N (EGL "
         "device N of the list); default: the surfaceless platform")
      ->type_name("G")
      ->trigger_on_parse()
      ->group(kGlGroup);
}

Result<std::unique_ptr<gl::Context>> open_context(const GlArgs& args, bool quiet) {
  if (args.gpu.kind != gl::GpuChoice::Kind::kDefault && args.backend == gl::Backend::kOsmesa)
    return make_error("--gpu: OSMesa has no EGL devices (give --backend egl or auto with --gpu)");
  gl::ContextDesc desc;
  desc.backend = args.backend;
  desc.gpu = args.gpu;
  auto context = gl::create_context(desc);
  if (context && !quiet && args.gpu.kind == gl::GpuChoice::Kind::kAuto)
    std::fprintf(stderr, "gpu: %s, %s\n", gl::backend_name(context.value()->backend()),
                 context.value()->egl_device().c_str());
  return context;
}

CLI::Option* add_output(CLI::App& app, const std::string& name, std::string& path, const std::string& value_name,
                        const std::string& help) {
  return app.add_option(name, path, help)->type_name(value_name)->group(kOutputGroup);
}

void add_stats_option(CLI::App& app, std::string& path) {
  app.add_option("--stats", path,
                 "per-frame numbers of the last frame: backend, egl_device, gl_renderer, reference_normal, "
                 "displacement, max_penetration, probe_position, timings_ms and gpu_timings_ms per pass, "
                 "skipped work")
      ->type_name("FILE.json")
      ->group(kOutputGroup);
}

void add_quiet_option(CLI::App& app, bool& quiet, const std::string& help) { app.add_flag("-q,--quiet", quiet, help); }

std::vector<std::string> switch_allow_paths(const SceneArgs& scene) {
  std::vector<std::string> out = scene.allow_paths;
  std::error_code ec;
  if (!scene.path.empty()) out.push_back(std::filesystem::absolute(scene.path, ec).parent_path().string());
  return out;
}

Result<Scene> load_scene_or_default(const SceneArgs& scene) {
  auto loaded = ps::load_scene_or_default(scene.path, scene.lines(), scene.allow_paths);
  if (loaded) return loaded;
  // The loader names a bad override "--set KEY: ..."; if the last value for KEY came from
  // another option (--velocity, --size, ...), name that option instead.
  const std::string& m = loaded.error().message;
  if (m.rfind("--set ", 0) != 0) return loaded;
  const std::string key = m.substr(6, m.find(':') - 6);
  for (auto o = scene.overrides.rbegin(); o != scene.overrides.rend(); ++o) {
    if (o->text.substr(0, o->text.find('=')) != key) continue;
    if (o->option == "--set") return loaded;
    return make_error(o->option + " (" + key + ")" + m.substr(6 + key.size()));
  }
  return loaded;
}

int scene_exit_code(const Error& e) { return e.message.rfind("--", 0) == 0 ? kExitUsage : kExitRuntime; }

std::string scene_display_name(const std::string& path) { return path.empty() ? kDefaultSceneName : path; }

void add_live_loop_options(CLI::App& app, LiveLoopArgs& args) {
  add_int(app, "--render-threads", "N", args.render_threads, 0, 1024,
          "llvmpipe's rasteriser threads (default: one fewer than the CPUs the program runs on, the spare one "
          "left out: none on 2 cores, so the 1 kHz loop keeps time; 0: every core; LP_NUM_THREADS in the "
          "environment wins)");
  app.add_option_function<std::string>(
         "--spare-cpu",
         [&args](const std::string& v) {  // checked as it is read: a bad value changes nothing
           if (auto plan = plan_spare_cpu(v, allowed_cpus()); !plan) throw UsageError(plan.error().message);
           args.spare_cpu = v;
         },
         "a CPU none of the program's threads use, so the kernel's own work lands there and not where "
         "the haptic thread runs: auto (default: the highest-numbered CPU, when the program may use two "
         "or more), off (the scheduler places every thread), or a CPU number")
      ->type_name("auto|off|N");
  app.add_option_function<std::string>(
         "--vibration-out",
         [&args](const std::string& v) {
           auto c = vibration::parse_output_choice(v);
           if (!c) throw UsageError(c.error().message);
           args.vibration_out = c.value();
         },
         "the texture under the probe as vibration (docs/vibration.md): none (default), sound (the default "
         "audio device, a channel of its own: wire an actuator to it), sound:DEVICE (an OpenAL device by "
         "name), gamepad (the first gamepad with rumble motors, SDL2), both, both:DEVICE")
      ->type_name("OUT");
}

std::unique_ptr<vibration::LiveVibration> open_live_vibration(const LiveLoopArgs& args, const Scene& scene,
                                                             HapticLoop& loop) {
  vibration::LiveDesc d;
  d.out = args.vibration_out;
  auto v = vibration::LiveVibration::open(d, scene);
  for (const std::string& w : v->warnings()) std::fprintf(stderr, "warning: %s\n", w.c_str());
  if (v->active()) loop.add_tick_feed(&v->feed());
  return v;
}

namespace {

// `cpus`: how many CPUs the program's threads run on (the spare one left out).
std::string apply_render_threads(int threads, std::size_t cpus) {
  if (const char* set = std::getenv("LP_NUM_THREADS"); set != nullptr && *set != '\0')
    return std::string(set) + " (LP_NUM_THREADS from the environment)";
  if (threads == 0) return "every core (llvmpipe's default)";
  // The thread that draws takes a CPU of its own: llvmpipe's rasterisers get the others. With one
  // CPU (2 cores, one of them spare) that is none: the rasteriser thread was the one the haptic
  // thread's wake-up failed to preempt (docs/haptics.md, "A spare CPU").
  const std::size_t n = threads > 0 ? static_cast<std::size_t>(threads) : (cpus > 1 ? cpus - 1 : 0);
  setenv("LP_NUM_THREADS", std::to_string(n).c_str(), 1);
  return std::to_string(n) + (threads > 0 ? "" : n == 0 ? " (the drawing thread rasterises)" : " (one per CPU beside the drawing thread)");
}

}  // namespace

std::string LiveLoopSetup::report() const { return "render threads " + render_threads + "; spare " + spare.description; }

Result<LiveLoopSetup> apply_live_loop(const LiveLoopArgs& args) {
  LiveLoopSetup setup;
  auto spare = leave_spare_cpu(args.spare_cpu);  // first: nothing is changed if the request is bad
  if (!spare) return spare.error();
  setup.spare = std::move(spare.value());
  const std::size_t cpus = setup.spare.spare >= 0 ? setup.spare.ours.size() : allowed_cpus().size();
  setup.render_threads = apply_render_threads(args.render_threads, std::max<std::size_t>(cpus, 1));
  keep_large_blocks_mapped();  // hours of running: worlds coming and going leave RSS flat
  return setup;
}

}  // namespace ps::cli
