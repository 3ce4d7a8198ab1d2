// `pseudoshadow tune`: headless parameter tuning: sweeps rendered into one labelled contact
// sheet, or a scripted console session read from stdin (docs/tuning.md).
#include <cstdio>
#include <iostream>
#include <unistd.h>

#include "app/cli_args.h"
#include "app/commands.h"
#include "core/output_set.h"
#include "gl/context.h"
#include "tune/console.h"
#include "tune/overrides_file.h"
#include "tune/sweep.h"

namespace ps {

namespace {

constexpr int kMaxCellSide = 2048;
constexpr long long kMaxCellPixels = 2048LL * 2048;

constexpr const char* kTuneHelp = R"(usage: pseudoshadow tune --scene FILE --sweep KEY=V1,V2,... [...] --out SHEET.png
       pseudoshadow tune --console [--scene FILE] < session.txt

Sweeps: renders the cross product of the sweeps (one render per cell, exactly as `render`
with --set KEY=VALUE) into one contact sheet, each cell labelled with its values.

options:
  --scene FILE            scene file (default: the built-in default scene)
  --sweep KEY=V1,V2,...   a sweep axis: listed values (TOML values; [..] arrays allowed)
  --sweep KEY=FROM:TO:STEPS   STEPS evenly spaced numbers, FROM and TO included (STEPS >= 2)
  --sweep-scenes A,B,...  a sweep axis over scene files (labelled by file name)
                          at most 256 cells in all; the last axis runs along a row
  --overrides FILE        apply an override file (KEY = VALUE lines) before --set
  --set KEY=VALUE         scene override for every cell (repeatable)
  --probe X,Y,Z           probe position, mm       --velocity VX,VY,VZ   probe velocity, mm/s
  --size WxH              size of each cell in pixels (max 2048 per side)
  --backend B             auto | egl | osmesa
  --out SHEET.png         the contact sheet (required for sweeps)
  --csv FILE              per-cell values and frame stats
                          (output directories: each must exist, or only its last
                          directory may be missing and is created; both files or neither)
  -q, --quiet             no progress output

Console (--console): commands from stdin, one per line: set KEY VALUE, render [N],
save FILE(.png|.exr|.toml), stats, reload, quit, # comment. Errors name the line and the
session continues; the exit status is 1 if any command failed.

exit status: 0 success, 1 runtime error, 2 usage error (bad option, sweep key or range)
)";

struct TuneArgs {
  std::string scene_path, out, csv, backend = "auto";
  std::vector<std::string> overrides;
  std::vector<SweepAxis> axes;
  bool console = false, quiet = false, help = false;
};

std::string vec_text(const glm::dvec3& v) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "[%.17g,%.17g,%.17g]", v.x, v.y, v.z);
  return buf;
}

Status parse_value_option(cli::ArgCursor& c, TuneArgs& a, bool& matched) {
  matched = true;
  if (auto v = c.option("--scene")) { if (!*v) return v->error(); a.scene_path = v->value(); return ok_status(); }
  if (auto v = c.option("--out")) { if (!*v) return v->error(); a.out = v->value(); return ok_status(); }
  if (auto v = c.option("--csv")) { if (!*v) return v->error(); a.csv = v->value(); return ok_status(); }
  if (auto v = c.option("--backend")) { if (!*v) return v->error(); a.backend = v->value(); return ok_status(); }
  if (auto v = c.option("--set")) { if (!*v) return v->error(); a.overrides.push_back(v->value()); return ok_status(); }
  if (auto v = c.option("--sweep")) {
    if (!*v) return v->error();
    auto axis = parse_sweep(v->value());
    if (!axis) return axis.error();
    a.axes.push_back(std::move(axis.value()));
    return ok_status();
  }
  if (auto v = c.option("--sweep-scenes")) {
    if (!*v) return v->error();
    auto axis = parse_scene_sweep(v->value());
    if (!axis) return axis.error();
    a.axes.push_back(std::move(axis.value()));
    return ok_status();
  }
  matched = false;
  return ok_status();
}

Status parse_one(cli::ArgCursor& c, TuneArgs& a) {
  bool matched = false;
  if (Status s = parse_value_option(c, a, matched); !s || matched) return s;
  if (auto v = c.option("--overrides")) {
    if (!*v) return v->error();
    auto lines = read_overrides(v->value());
    if (!lines) return lines.error();
    a.overrides.insert(a.overrides.end(), lines->begin(), lines->end());
    return ok_status();
  }
  for (const char* name : {"--probe", "--velocity"}) {
    if (auto v = c.option(name)) {
      if (!*v) return v->error();
      auto p = cli::parse_vec3(name, v->value(), "0,0,10");
      if (!p) return p.error();
      a.overrides.push_back(std::string(name[2] == 'p' ? "probe.position=" : "probe.velocity=") + vec_text(*p));
      return ok_status();
    }
  }
  if (auto v = c.option("--size")) {
    if (!*v) return v->error();
    auto sz = cli::parse_size(v->value(), kMaxCellSide, kMaxCellPixels);
    if (!sz) return sz.error();
    a.overrides.push_back("render.size=[" + std::to_string(sz->x) + "," + std::to_string(sz->y) + "]");
    return ok_status();
  }
  if (c.flag("--console")) { a.console = true; return ok_status(); }
  if (c.flag("-q") || c.flag("--quiet")) { a.quiet = true; return ok_status(); }
  if (c.flag("-h") || c.flag("--help")) { a.help = true; return ok_status(); }
  return make_error("unknown option '" + std::string(c.peek()) + "' (see pseudoshadow tune --help)");
}

int fail(const Error& e, int code) {
  std::fprintf(stderr, "pseudoshadow tune: %s\n", e.message.c_str());
  return code;
}

void print_progress(std::size_t done, std::size_t total, const std::string& label, bool tty) {
  if (!tty) {
    std::fprintf(stderr, "cell %zu/%zu %s\n", done, total, label.c_str());
    return;
  }
  constexpr int kBar = 30;
  const int filled = static_cast<int>(kBar * done / total);
  std::fprintf(stderr, "\r[%.*s%*s] %zu/%zu %-40.40s", filled, "##############################",
               kBar - filled, "", done, total, label.c_str());
  if (done == total) std::fputc('\n', stderr);
}

int run_sweep(const TuneArgs& a) {
  // Both outputs checked before the sweep and published together after it (or neither).
  OutputSet outputs;
  if (Status s = outputs.add(a.out); !s) return fail(s.error(), 1);
  if (!a.csv.empty())
    if (Status s = outputs.add(a.csv); !s) return fail(s.error(), 1);
  SweepJob job{a.scene_path, a.overrides, a.axes, {}};
  const bool tty = isatty(STDERR_FILENO);
  auto cells = render_sweep(job, [&](std::size_t done, std::size_t total, const std::string& label) {
    if (!a.quiet) print_progress(done, total, label, tty);
  });
  if (!cells) return fail(cells.error(), 1);
  const Image sheet = sweep_sheet(a.axes, cells.value());
  if (Status s = stage_image(outputs, a.out, sheet); !s) return fail(s.error(), 1);
  if (!a.csv.empty())
    if (Status s = outputs.stage_text(a.csv, sweep_csv(a.axes, cells.value())); !s) return fail(s.error(), 1);
  if (Status s = outputs.publish(); !s) return fail(s.error(), 1);
  if (!a.quiet) std::printf("wrote %s (%zu cells, %dx%d)\n", a.out.c_str(), cells->size(), sheet.width, sheet.height);
  return 0;
}

int run_console_mode(const TuneArgs& a) {
  auto session = TuneSession::open({a.scene_path, a.overrides, {}});
  if (!session) return fail(session.error(), 1);
  const ConsoleResult r = run_console(*session.value(), std::cin, std::cout, std::cerr);
  return r.errors == 0 ? 0 : 1;
}

}  // namespace

int run_tune(int argc, char** argv) {
  TuneArgs a;
  cli::ArgCursor c(argc, argv, 1);
  while (!c.done())
    if (Status s = parse_one(c, a); !s) return fail(s.error(), 2);
  if (a.help) { std::fputs(kTuneHelp, stdout); return 0; }
  if (a.console && !a.axes.empty()) return fail(make_error("--console and --sweep cannot be combined"), 2);
  if (!a.console && a.axes.empty())
    return fail(make_error("nothing to do: give --sweep KEY=... (and --out SHEET.png) or --console"), 2);
  if (!a.console && a.out.empty()) return fail(make_error("--out SHEET.png is required for a sweep"), 2);
  if (auto n = sweep_cell_count(a.axes); !n) return fail(n.error(), 2);
  auto backend = gl::parse_backend(a.backend);
  if (!backend) return fail(make_error("--backend: " + backend.error().message), 2);
  gl::ContextDesc desc;
  desc.backend = backend.value();
  if (!a.console) {
    // Validate before creating the context: bad keys and values fail fast, exit 2.
    // A bad sweep key or value is a usage error (2); a broken scene file a runtime one (1).
    if (Status s = validate_sweep({a.scene_path, a.overrides, a.axes, {}}); !s)
      return fail(s.error(), s.error().message.rfind("--sweep", 0) == 0 ? 2 : 1);
  }
  auto ctx = gl::create_context(desc);
  if (!ctx) return fail(ctx.error(), 1);
  return a.console ? run_console_mode(a) : run_sweep(a);
}

}  // namespace ps
