// `pseudoshadow replay`: renders a recorded or scripted device session headless at a fixed
// frame rate, deterministically (fake clock, no threads), and writes the frames.
#include <cstdio>
#include <unistd.h>

#include "app/cli_args.h"
#include "app/commands.h"
#include "app/session.h"
#include "core/output_set.h"
#include "devices/sample_log.h"
#include "gl/context.h"
#include "image/text.h"
#include "scene/scene_io.h"

namespace ps {

namespace {

constexpr const char* kReplayHelp = R"(usage: pseudoshadow replay --log FILE --out DIR [options]

Renders the frames of a device session (a recording made with `run --record`, or a scripted
trajectory) headless at a fixed frame rate. Deterministic: the haptic loop runs on a fake
clock, so the same log and scene always give byte-identical images.

options:
  --scene FILE            scene file (default: the built-in default scene)
  --log [KIND:]FILE       device log, lines 'time_s x y z buttons'; KIND playback (default:
                          sample-and-hold, exact) or trajectory (linear interpolation)
  --out DIR               writes DIR/frame_00000.png ... (DIR is created if its parent
                          exists; frames and sheet are all written, or none)
  --every N               write every N-th frame (default 1)
  --fps F                 frames per second of session time (default 30)
  --contact-sheet FILE    also one labelled sheet of the written frames (PNG)
  --record FILE           record the device stream the loop read (a playback log)
  --set KEY=VALUE         scene override (as for render)
  --backend B             auto | egl | osmesa
  --show-probe            also draw the probe itself (the haptic proxy) in the frames
  -q, --quiet             no progress
  -h, --help              this text

exit status: 0 success, 1 runtime error, 2 usage error
)";

struct ReplayArgs {
  std::string scene_path, log, out_dir, sheet, record, backend = "auto";
  std::vector<std::string> overrides;
  long long every = 1;
  double fps = 30.0;
  bool quiet = false, help = false, show_probe = false;
};

Status parse_one(cli::ArgCursor& c, ReplayArgs& a) {
  auto str = [&](std::string_view name, std::string& dst) -> std::optional<Status> {
    auto v = c.option(name);
    if (!v) return std::nullopt;
    if (!*v) return Status(v->error());
    dst = v->value();
    return ok_status();
  };
  using S = std::optional<Status>;
  std::string tmp;
  if (S s = str("--scene", a.scene_path)) return *s;
  if (S s = str("--log", a.log)) return *s;
  if (S s = str("--out", a.out_dir)) return *s;
  if (S s = str("--contact-sheet", a.sheet)) return *s;
  if (S s = str("--record", a.record)) return *s;
  if (S s = str("--backend", a.backend)) return *s;
  if (S s = str("--set", tmp)) { if (*s) a.overrides.push_back(tmp); return *s; }
  if (S s = str("--every", tmp); s) {
    if (!*s) return *s;
    auto n = cli::parse_int("--every", tmp, 1, 1'000'000);
    if (!n) return n.error();
    a.every = n.value();
    return ok_status();
  }
  if (S s = str("--fps", tmp); s) {
    if (!*s) return *s;
    char* end = nullptr;
    a.fps = std::strtod(tmp.c_str(), &end);
    if (end != tmp.c_str() + tmp.size() || !(a.fps > 0.0 && a.fps <= 10000.0))
      return make_error("--fps: expected a number in (0, 10000], e.g. --fps 30");
    return ok_status();
  }
  if (c.flag("--show-probe")) { a.show_probe = true; return ok_status(); }
  if (c.flag("-q") || c.flag("--quiet")) { a.quiet = true; return ok_status(); }
  if (c.flag("-h") || c.flag("--help")) { a.help = true; return ok_status(); }
  return make_error("unknown option '" + std::string(c.peek()) + "' (see pseudoshadow replay --help)");
}

Image thumbnail(const Image& im, int width) {
  Image t;
  t.width = std::min(width, im.width);
  t.height = std::max(1, t.width * im.height / im.width);
  t.channels = 3;
  t.pixels.resize(static_cast<size_t>(t.width) * t.height * 3);
  for (int y = 0; y < t.height; ++y)
    for (int x = 0; x < t.width; ++x)
      for (int c = 0; c < 3; ++c) t.at(x, y, c) = im.at(x * im.width / t.width, y * im.height / t.height, c);
  return t;
}

struct ReplayGl {  // context first: the renderer's GL objects die before it
  std::unique_ptr<gl::Context> ctx;
  std::unique_ptr<Renderer> renderer;
};

Result<ReplayGl> open_renderer(const ReplayArgs& a) {
  auto scene = a.scene_path.empty()
                   ? parse_scene(default_scene_text(), "<built-in default scene>", default_scene_base_dir(), a.overrides)
                   : load_scene(a.scene_path, a.overrides);
  if (!scene) return scene.error();
  auto backend = gl::parse_backend(a.backend);
  if (!backend) return backend.error();
  auto ctx = gl::create_context({backend.value()});
  if (!ctx) return ctx.error();
  auto renderer = Renderer::create(scene.value(), {});
  if (!renderer) return renderer.error();
  renderer.value()->set_show_probe(a.show_probe);
  return ReplayGl{std::move(ctx.value()), std::move(renderer.value())};
}

std::string frame_path(const ReplayArgs& a, int i) {
  char name[32];
  std::snprintf(name, sizeof name, "/frame_%05d.png", i);
  return a.out_dir + name;
}

// Checked before the session: frames and sheet are published together at the end, or not at
// all. The --record log streams to its own "<FILE>.partial" (SampleRecorder) and is published
// by the session when it ends; only its directory is checked here.
Status add_outputs(const ReplayArgs& a, OutputSet& out) {
  if (Status s = out.add(frame_path(a, 0)); !s) return s;
  if (!a.sheet.empty())
    if (Status s = out.add(a.sheet); !s) return s;
  if (!a.record.empty())
    if (Status s = prepare_output_dir(a.record); !s) return s;
  return ok_status();
}

int replay(const ReplayArgs& a) {
  auto fail = [](const Error& e) { std::fprintf(stderr, "pseudoshadow replay: %s\n", e.message.c_str()); return 1; };
  OutputSet outputs;
  if (Status s = add_outputs(a, outputs); !s) return fail(s.error());
  const std::string spec = a.log.find(':') == std::string::npos ? "playback:" + a.log : a.log;
  auto device = open_log_device(spec);
  if (!device) return fail(device.error());
  auto gl_state = open_renderer(a);
  if (!gl_state) return fail(gl_state.error());
  Renderer* renderer = gl_state->renderer.get();
  ReplayOptions opt;
  opt.fps = a.fps;
  opt.record_path = a.record;
  opt.progress = !a.quiet && isatty(STDERR_FILENO);
  std::vector<Image> thumbs;
  std::vector<std::string> labels;
  int written = 0;
  auto sink = [&](int i, double t, const HapticState& st, const Renderer& r) -> Status {
    if (i % a.every != 0) return ok_status();
    const Image img = r.read_color();
    if (Status s = stage_image(outputs, frame_path(a, i), img); !s) return s;
    ++written;
    if (!a.sheet.empty()) {
      char label[64];
      std::snprintf(label, sizeof label, "%d t=%.2f s v=%.0f mm/s", i, t, glm::length(st.velocity_mm_s));
      thumbs.push_back(thumbnail(img, 256));
      labels.emplace_back(label);
    }
    return ok_status();
  };
  auto result = replay_session(*renderer, *device.value(), opt, sink);
  if (!result) return fail(result.error());
  if (!a.sheet.empty())
    if (Status s = stage_image(outputs, a.sheet, contact_sheet(thumbs, labels)); !s) return fail(s.error());
  if (Status s = outputs.publish(); !s) return fail(s.error());
  if (!a.quiet)
    std::printf("replayed %d frames at %g fps, wrote %d images to %s; rejected device samples: %llu\n",
                result->frames, a.fps, written, a.out_dir.c_str(),
                static_cast<unsigned long long>(result->rejected.total()));
  return 0;
}

}  // namespace

int run_replay(int argc, char** argv) {
  ReplayArgs a;
  cli::ArgCursor c(argc, argv, 1);
  while (!c.done()) {
    if (Status s = parse_one(c, a); !s) {
      std::fprintf(stderr, "pseudoshadow replay: %s\n", s.error().message.c_str());
      return 2;
    }
  }
  if (a.help) { std::fputs(kReplayHelp, stdout); return 0; }
  if (a.log.empty() || a.out_dir.empty()) {
    std::fputs("pseudoshadow replay: --log FILE and --out DIR are required (see --help)\n", stderr);
    return 2;
  }
  return replay(a);
}

}  // namespace ps
