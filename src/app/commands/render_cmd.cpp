// `pseudoshadow render`: renders a scene headless and writes the image, AOVs and stats.
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <unistd.h>

#include "app/cli/cli.h"
#include "app/cli/cli_groups.h"
#include "app/commands.h"
#include "core/output_set.h"
#include "gl/context.h"
#include "prepare/prepare.h"
#include "render/renderer.h"
#include "render/scene_frames.h"

namespace ps {

namespace {

// The distance AOV is float mm with NaN outside the shadow: only float formats keep it.
constexpr std::string_view kFloatImageExtensions[] = {".exr", ".tif", ".tiff", ".hdr", ".pfm"};

constexpr const char* kDescription =
    "Renders a scene headless (EGL or OSMesa) and writes the image.";

struct RenderArgs {
  cli::SceneArgs scene;
  cli::GlArgs gl_opts;
  std::string out = "render.png", stats_path;
  std::vector<std::pair<std::string, std::string>> aovs;
  bool quiet = false, show_probe = false;
  std::string reductions = "compute";
};

void check_aov(const std::string& name, const std::string& file) {
  const Result<Aov> aov = parse_aov(name);
  if (!aov) throw cli::UsageError("--aov: " + aov.error().message);
  std::string ext = std::filesystem::path(file).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (aov.value() == Aov::kDistance && std::find(std::begin(kFloatImageExtensions), std::end(kFloatImageExtensions), ext) ==
                                std::end(kFloatImageExtensions))
    throw cli::UsageError("--aov distance=" + file + ": the distance AOV is float mm (NaN outside the shadow) "
                          "and needs a float format: write distance=" +
                          std::filesystem::path(file).replace_extension(".exr").string() + " (or .tif, .hdr, .pfm)");
}

void declare(cli::Command& cmd, RenderArgs& a) {
  CLI::App& app = cmd.app();
  cli::add_scene_options(app, a.scene);
  cli::add_probe_options(app, a.scene);
  cli::add_image_options(app, a.scene);
  cli::add_ordered(app, "--frames", "N",
                   "frames to run (sets render.frames; reference plane and displacement update each "
                   "frame); the last one is written",
                   [&a](const std::string& v) {
                     a.scene.add("render.frames=" + std::to_string(cli::parse_int("--frames", v, 1, 100000)), "--frames");
                   })
      ->group(cli::kSceneGroup);
  cli::add_gl_options(app, a.gl_opts);
  app.add_option("--out", a.out, std::string("output image (default: render.png). ") + cli::kOutputRule)->type_name("IMAGE.png")->group(cli::kOutputGroup);
  cli::add_ordered(app, "--aov", "NAME=FILE",
                   "also write an AOV (repeatable): intensity, distance (float mm, NaN outside the shadow; "
                   ".exr, .tif, .hdr or .pfm), texture (Gabor value in sigmas, before speed modulation), "
                   "normal, displacement (weighted displacement xyz, weight w)",
                   [&a](const std::string& v) {
                     const size_t eq = v.find('=');
                     if (eq == std::string::npos || eq == 0 || eq + 1 == v.size())
                       throw cli::UsageError("--aov: expected NAME=FILE, e.g. --aov intensity=intensity.exr");
                     check_aov(v.substr(0, eq), v.substr(eq + 1));
                     a.aovs.emplace_back(v.substr(0, eq), v.substr(eq + 1));
                   })
      ->group(cli::kOutputGroup);
  cli::add_stats_option(app, a.stats_path);
  app.add_flag("--show-probe", a.show_probe,
               "also draw the probe itself (where the haptic proxy is, after the push-out) over the "
               "pseudo-shadow; AOVs and stats are unchanged");
  app.add_option("--reductions", a.reductions,
                 "how the reductions (maximum penetration, displacement, mean normal) run: compute "
                 "(default; compute shaders) or fragment (fragment shaders, the rows added on the "
                 "host: the path a WebGL2 build has); the same image, AOVs and stats bit for bit")
      ->check(CLI::IsMember({"compute", "fragment"}))
      ->type_name("compute|fragment")
      ->group(cli::kGlGroup);
  cli::add_quiet_option(app, a.quiet);
}

// The scene's frames as the library draws them too (render/scene_frames.h), with a progress line.
Status run_frames(Renderer& r, int frames, bool progress) {
  const auto t0 = std::chrono::steady_clock::now();
  return render_scene_frames(r, frames, [&](int i) {
    if (!progress) return;
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::fprintf(stderr, "\rframe %d/%d  %.1f s", i + 1, frames, secs);
    if (i + 1 == frames) std::fputc('\n', stderr);
  });
}

// Every output path is checked before the render (a typo in --stats must not cost a render) and
// all are published together after it: a failed command leaves none of them (docs/errors.md).
Status add_outputs(const RenderArgs& a, OutputSet& out) {
  if (Status s = out.add(a.out); !s) return s;
  for (const auto& [name, file] : a.aovs)
    if (Status s = out.add(file); !s) return s;
  if (!a.stats_path.empty())
    if (Status s = out.add(a.stats_path); !s) return s;
  return ok_status();
}

Status write_outputs(const RenderArgs& a, const Renderer& r, const gl::Context& ctx, OutputSet& out) {
  if (Status s = stage_image(out, a.out, r.read_color()); !s) return s;
  for (const auto& [name, file] : a.aovs) {
    auto img = r.read_aov(name);
    if (!img) return img.error();
    if (Status s = stage_image(out, file, img.value()); !s) return s;
  }
  if (!a.stats_path.empty()) {
    const std::string json = stats_json(r.stats(), gl::backend_name(ctx.backend()), ctx.egl_device(), ctx.renderer(),
                                        r.scene().render.frames);
    if (Status s = out.stage_text(a.stats_path, json); !s) return s;
  }
  return out.publish();
}

int render(const cli::Command& cmd, const RenderArgs& a) {
  OutputSet outputs;  // every output path checked before any work
  if (Status s = add_outputs(a, outputs); !s) return cmd.fail(s.error());
  auto scene = cli::load_scene_or_default(a.scene);
  if (!scene) return cmd.fail(scene.error(), cli::scene_exit_code(scene.error()));
  auto ctx = cli::open_context(a.gl_opts, a.quiet);
  if (!ctx) return cmd.fail(ctx.error());
  auto view = make_view(scene.value(), ViewFlags{a.show_probe, false, false});  // the scene's start view
  if (!view) return cmd.fail(view.error());
  RendererOptions options;
  options.expected_frames = scene->render.frames;  // a short render skips a tile bake it would not repay
  options.view = view.value();
  options.reductions = a.reductions == "fragment" ? ReductionMethod::kFragment : ReductionMethod::kCompute;
  auto renderer = open_renderer(scene.value(), options);
  if (!renderer) return cmd.fail(renderer.error());
  const int frames = scene->render.frames;
  const bool progress = !a.quiet && frames > 1 && isatty(STDERR_FILENO);
  if (Status s = run_frames(*renderer.value(), frames, progress); !s) return cmd.fail(s.error());
  renderer.value()->poll_gpu_timings(true);  // the last frame's timers: its image is read next anyway
  if (Status s = write_outputs(a, *renderer.value(), *ctx.value(), outputs); !s) return cmd.fail(s.error());
  if (!a.quiet) {
    double frame_ms = 0.0;
    for (const auto& [n, ms] : renderer.value()->stats().timings_ms) frame_ms += ms;
    std::printf("wrote %s (%dx%d, %s, %d frame%s, last frame %.1f ms)\n", a.out.c_str(),
                scene->render.width, scene->render.height, gl::backend_name(ctx.value()->backend()),
                frames, frames == 1 ? "" : "s", frame_ms);
  }
  return cli::kExitOk;
}

}  // namespace

int run_render(int argc, char** argv) {
  return cli::run_command<RenderArgs>(argc, argv, "render", kDescription, declare, render);
}

}  // namespace ps
