// `pseudoshadow bench`: sweeps the accuracy knobs on an analytic scene, writes a CSV, a
// Markdown summary and a time-vs-error plot with the Pareto fronts (docs/benchmarks.md).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "app/bench_report.h"
#include "app/bench_sweep.h"
#include "app/cli_args.h"
#include "app/commands.h"
#include "core/output_set.h"
#include "gl/context.h"

namespace ps {

namespace {

constexpr const char* kBenchHelp = R"(usage: pseudoshadow bench [options]

Sweeps the accuracy knobs (reduction base resolution, probe depth-map size, Gabor impulses per
kernel n, kernel truncation, Gabor evaluation strategy, displacement method) on an analytic
scene (flat plane, orthographic camera, sphere probe 0.5 mm deep) and measures frame time and
error against the CPU reference on the same frame. Also measures the skip ratios and the peak
RSS of `pseudoshadow render` at 512x512 and 2048x2048. Takes a few minutes on 2 cores.

options:
  --size N          image side in pixels for the sweep (default 512; 64..2048)
  --frames N        timed warm frames per configuration and round (default 3); every
                    configuration is measured in 3 round-robin rounds, the median over
                    all its timed frames is reported
  --out-dir DIR     output directory (default bench_out): bench.csv, bench.png, bench.md;
                    created if its parent exists
  --backend B       auto (EGL, then OSMesa) | egl | osmesa
  -q, --quiet       no progress output
  -h, --help        this text

exit status: 0 success, 1 runtime error, 2 usage error
)";

struct BenchArgs {
  int size = 512, frames = 3;
  std::string out_dir = "bench_out", backend = "auto";
  bool quiet = false, help = false;
};

Status parse_one(cli::ArgCursor& c, BenchArgs& a) {
  if (auto v = c.option("--size")) {
    if (!*v) return v->error();
    auto n = cli::parse_int("--size", v->value(), 64, 2048);
    if (!n) return n.error();
    a.size = static_cast<int>(n.value());
    return ok_status();
  }
  if (auto v = c.option("--frames")) {
    if (!*v) return v->error();
    auto n = cli::parse_int("--frames", v->value(), 1, 1000);
    if (!n) return n.error();
    a.frames = static_cast<int>(n.value());
    return ok_status();
  }
  if (auto v = c.option("--out-dir")) return *v ? (a.out_dir = v->value(), ok_status()) : Status(v->error());
  if (auto v = c.option("--backend")) return *v ? (a.backend = v->value(), ok_status()) : Status(v->error());
  if (c.flag("-q") || c.flag("--quiet")) { a.quiet = true; return ok_status(); }
  if (c.flag("-h") || c.flag("--help")) { a.help = true; return ok_status(); }
  return make_error("unknown option '" + std::string(c.peek()) + "' (see pseudoshadow bench --help)");
}

Status run(const BenchArgs& a, gl::Backend backend) {
  // The results (CSV and summary) are checked now and published together at the end, or not at
  // all. The plot is extra (it needs gnuplot) and is drawn after them; the RSS renders and the
  // plot's data files are work files in the same directory.
  OutputSet outputs;
  const std::string csv = a.out_dir + "/bench.csv", md_path = a.out_dir + "/bench.md";
  if (Status s = outputs.add(csv); !s) return s;
  if (Status s = outputs.add(md_path); !s) return s;
  bench::BenchOptions o;
  o.size = a.size;
  o.timed_frames = a.frames;
  if (!a.quiet) o.progress = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); };
  bench::SkipRatios skip;
  std::vector<bench::BenchRow> rows;
  {
    gl::ContextDesc desc;
    desc.backend = backend;
    auto ctx = gl::create_context(desc);
    if (!ctx) return ctx.error();
    auto r = bench::run_sweep(o);
    if (!r) return r.error();
    rows = std::move(r.value());
    if (o.progress) o.progress("skip ratios ...");
    auto s = bench::run_skip_ratios(o);
    if (!s) return s.error();
    skip = s.value();
  }
  bench::RssReport rss;
  const std::string bname = a.backend;
  for (int size : {512, 2048}) {
    if (o.progress) o.progress("peak RSS of render " + std::to_string(size) + "^2 ...");
    auto k = bench::render_peak_rss_kib(size, bname, a.out_dir);
    if (!k) return k.error();
    (size == 512 ? rss.kib_512 : rss.kib_2048) = k.value();
  }
  const std::string md = bench::summary_markdown(rows, skip, rss, a.size);
  if (Status s = outputs.stage_text(csv, bench::csv_text(rows)); !s) return s;
  if (Status s = outputs.stage_text(md_path, md); !s) return s;
  if (Status s = outputs.publish(); !s) return s;
  if (!a.quiet) std::fputs(md.c_str(), stdout);
  if (Status s = bench::write_plot(a.out_dir + "/bench.png", a.out_dir, rows); !s)
    std::fprintf(stderr, "pseudoshadow bench: %s\n", s.error().message.c_str());
  return ok_status();
}

}  // namespace

int run_bench(int argc, char** argv) {
  BenchArgs a;
  cli::ArgCursor c(argc, argv, 1);
  while (!c.done()) {
    if (Status s = parse_one(c, a); !s) {
      std::fprintf(stderr, "pseudoshadow bench: %s\n", s.error().message.c_str());
      return 2;
    }
  }
  if (a.help) { std::fputs(kBenchHelp, stdout); return 0; }
  auto backend = gl::parse_backend(a.backend);
  if (!backend) {
    std::fprintf(stderr, "pseudoshadow bench: --backend: %s\n", backend.error().message.c_str());
    return 2;
  }
  if (Status s = run(a, backend.value()); !s) {
    std::fprintf(stderr, "pseudoshadow bench: %s\n", s.error().message.c_str());
    return 1;
  }
  return 0;
}

}  // namespace ps
