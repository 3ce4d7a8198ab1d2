// `pseudoshadow render`: renders a scene headless and writes the image, AOVs and stats.
#include <cerrno>
#include <chrono>
#include <cstring>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <unistd.h>

#include "app/cli_args.h"
#include "app/commands.h"
#include "core/output_set.h"
#include "gl/context.h"
#include "render/renderer.h"
#include "scene/scene_io.h"
#include "tune/overrides_file.h"

namespace ps {

namespace {

constexpr int kMaxSide = 8192;               // GL_MAX_TEXTURE_SIZE-safe on llvmpipe
constexpr long long kMaxPixels = 16'777'216;  // 4096^2: keeps the padded targets < 1.2 GiB

constexpr const char* kRenderHelp = R"(usage: pseudoshadow render [options]

Renders a scene headless (EGL or OSMesa) and writes the image.

options:
  --scene FILE          scene file (TOML, docs/scene-format.md); default: the built-in
                        default scene (scenes/default.toml)
  --probe X,Y,Z         probe position in mm (overrides probe.position)
  --velocity VX,VY,VZ   probe velocity in mm/s (overrides probe.velocity); drives the
                        texture amplitude
  --size WxH            image size in pixels (max 8192 per side, 16777216 pixels)
  --frames N            frames to run (reference plane and displacement update each frame);
                        the last one is written
  --backend B           auto (EGL, then OSMesa) | egl | osmesa
  --set KEY=VALUE       override any scene value by its path, e.g.
                        --set materials.wood.lambda_min=0.4 --set render.displacement=exact_max
                        (repeatable; VALUE is a TOML value: 0.4, [0,0,5], exact_max, "text")
  --overrides FILE      apply an override file saved by `run`/`tune` (KEY = VALUE lines,
                        docs/tuning.md) at this point of the --set list
  --out IMAGE.png       output image (default: render.png). For every output file: its
                        directory must exist, or only its last directory may be missing
                        (it is created); all outputs are written, or none
  --aov NAME=FILE.exr   also write an AOV: intensity, distance (mm; NaN: no probe above),
                        texture (Gabor value in sigmas, before speed modulation), normal,
                        displacement (weighted displacement xyz, weight w) (repeatable)
  --show-probe          also draw the probe itself (where the haptic proxy is, after the
                        push-out) over the pseudo-shadow; AOVs and stats are unchanged
  --stats FILE.json     per-frame numbers of the last frame: backend, gl_renderer,
                        reference_normal, displacement, max_penetration, probe_position,
                        timings_ms per pass, skipped work
  -q, --quiet           no progress output
  -h, --help            this text

exit status: 0 success, 1 runtime error (bad scene, no GL context, write failure), 2 usage error
)";

struct RenderArgs {
  std::string scene_path, out = "render.png", stats_path, backend = "auto";
  std::vector<std::string> overrides;
  std::vector<std::pair<std::string, std::string>> aovs;
  bool quiet = false, help = false, show_probe = false;
};

std::string fmt_vec(const glm::dvec3& v) {
  std::ostringstream o;
  o.precision(17);
  o << "[" << v.x << "," << v.y << "," << v.z << "]";
  return o.str();
}

Status parse_one(cli::ArgCursor& c, RenderArgs& a) {
  auto take = [&](std::string_view name, auto&& apply) -> std::optional<Status> {
    auto v = c.option(name);
    if (!v) return std::nullopt;
    if (!*v) return Status(v->error());
    return apply(v->value());
  };
  using S = std::optional<Status>;
  if (S s = take("--scene", [&](const std::string& v) { a.scene_path = v; return ok_status(); })) return *s;
  if (S s = take("--out", [&](const std::string& v) { a.out = v; return ok_status(); })) return *s;
  if (S s = take("--stats", [&](const std::string& v) { a.stats_path = v; return ok_status(); })) return *s;
  if (S s = take("--backend", [&](const std::string& v) { a.backend = v; return ok_status(); })) return *s;
  if (S s = take("--set", [&](const std::string& v) { a.overrides.push_back(v); return ok_status(); })) return *s;
  if (S s = take("--overrides", [&](const std::string& v) -> Status {
        auto lines = read_overrides(v);
        if (!lines) return lines.error();
        a.overrides.insert(a.overrides.end(), lines->begin(), lines->end());
        return ok_status();
      })) return *s;
  if (S s = take("--probe", [&](const std::string& v) -> Status {
        auto p = cli::parse_vec3("--probe", v, "0,0,10");
        if (!p) return p.error();
        a.overrides.push_back("probe.position=" + fmt_vec(p.value()));
        return ok_status();
      })) return *s;
  if (S s = take("--velocity", [&](const std::string& v) -> Status {
        auto p = cli::parse_vec3("--velocity", v, "120,0,0");
        if (!p) return p.error();
        a.overrides.push_back("probe.velocity=" + fmt_vec(p.value()));
        return ok_status();
      })) return *s;
  if (S s = take("--size", [&](const std::string& v) -> Status {
        auto sz = cli::parse_size(v, kMaxSide, kMaxPixels);
        if (!sz) return sz.error();
        a.overrides.push_back("render.size=[" + std::to_string(sz->x) + "," + std::to_string(sz->y) + "]");
        return ok_status();
      })) return *s;
  if (S s = take("--frames", [&](const std::string& v) -> Status {
        auto n = cli::parse_int("--frames", v, 1, 100000);
        if (!n) return n.error();
        a.overrides.push_back("render.frames=" + std::to_string(n.value()));
        return ok_status();
      })) return *s;
  if (S s = take("--aov", [&](const std::string& v) -> Status {
        const size_t eq = v.find('=');
        if (eq == std::string::npos || eq == 0 || eq + 1 == v.size())
          return make_error("--aov: expected NAME=FILE, e.g. --aov intensity=intensity.exr");
        a.aovs.emplace_back(v.substr(0, eq), v.substr(eq + 1));
        return ok_status();
      })) return *s;
  if (c.flag("--show-probe")) { a.show_probe = true; return ok_status(); }
  if (c.flag("-q") || c.flag("--quiet")) { a.quiet = true; return ok_status(); }
  if (c.flag("-h") || c.flag("--help")) { a.help = true; return ok_status(); }
  return make_error("unknown option '" + std::string(c.peek()) + "' (see pseudoshadow render --help)");
}

Result<Scene> load(const RenderArgs& a) {
  if (a.scene_path.empty())
    return parse_scene(default_scene_text(), "<built-in default scene>", default_scene_base_dir(), a.overrides);
  return load_scene(a.scene_path, a.overrides);
}

Status check_aov_names(const RenderArgs& a) {
  for (const auto& [name, file] : a.aovs) {
    bool known = false;
    for (const auto& n : aov_names()) known = known || n == name;
    if (!known) {
      std::string list;
      for (const auto& n : aov_names()) list += (list.empty() ? "" : ", ") + n;
      return make_error("--aov: unknown AOV '" + name + "' (known: " + list + ")");
    }
  }
  return ok_status();
}

Status run_frames(Renderer& r, int frames, bool progress) {
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < frames; ++i) {
    if (Status s = r.render_frame(); !s) return s;
    if (progress) {
      const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::fprintf(stderr, "\rframe %d/%d  %.1f s", i + 1, frames, secs);
      if (i + 1 == frames) std::fputc('\n', stderr);
    }
  }
  return ok_status();
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
    const std::string json = stats_json(r.stats(), gl::backend_name(ctx.backend()), ctx.renderer(),
                                        r.scene().render.frames);
    if (Status s = out.stage_text(a.stats_path, json); !s) return s;
  }
  return out.publish();
}

}  // namespace

int run_render(int argc, char** argv) {
  RenderArgs a;
  cli::ArgCursor c(argc, argv, 1);
  while (!c.done()) {
    if (Status s = parse_one(c, a); !s) {
      std::fprintf(stderr, "pseudoshadow render: %s\n", s.error().message.c_str());
      return 2;
    }
  }
  if (a.help) { std::fputs(kRenderHelp, stdout); return 0; }
  auto fail = [](const Error& e) { std::fprintf(stderr, "pseudoshadow render: %s\n", e.message.c_str()); return 1; };
  auto backend = gl::parse_backend(a.backend);
  if (!backend) { std::fprintf(stderr, "pseudoshadow render: --backend: %s\n", backend.error().message.c_str()); return 2; }
  if (Status s = check_aov_names(a); !s) { std::fprintf(stderr, "pseudoshadow render: %s\n", s.error().message.c_str()); return 2; }
  OutputSet outputs;
  if (Status s = add_outputs(a, outputs); !s) return fail(s.error());
  auto scene = load(a);
  if (!scene) return fail(scene.error());
  gl::ContextDesc desc;
  desc.backend = backend.value();
  auto ctx = gl::create_context(desc);
  if (!ctx) return fail(ctx.error());
  auto renderer = Renderer::create(scene.value(), {});
  if (!renderer) return fail(renderer.error());
  renderer.value()->set_show_probe(a.show_probe);
  const int frames = scene->render.frames;
  const bool progress = !a.quiet && frames > 1 && isatty(STDERR_FILENO);
  if (Status s = run_frames(*renderer.value(), frames, progress); !s) return fail(s.error());
  if (Status s = write_outputs(a, *renderer.value(), *ctx.value(), outputs); !s) return fail(s.error());
  if (!a.quiet) {
    double frame_ms = 0.0;
    for (const auto& [n, ms] : renderer.value()->stats().timings_ms) frame_ms += ms;
    std::printf("wrote %s (%dx%d, %s, %d frame%s, last frame %.1f ms)\n", a.out.c_str(),
                scene->render.width, scene->render.height, gl::backend_name(ctx.value()->backend()),
                frames, frames == 1 ? "" : "s", frame_ms);
  }
  return 0;
}

}  // namespace ps
