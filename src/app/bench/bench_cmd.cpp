// `pseudoshadow bench`: sweeps the accuracy knobs on an analytic scene, writes a CSV, a
// Markdown summary and a time-vs-error plot with the Pareto fronts (docs/benchmarks.md).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

#include "app/bench/bench_first_image.h"
#include "core/file_io.h"
#include "app/bench/bench_moving.h"
#include "app/bench/bench_plot.h"
#include "app/bench/bench_report.h"
#include "app/bench/bench_sweep.h"
#include "app/bench/bench_texture_filter.h"
#include "app/cli/cli.h"
#include "app/cli/cli_groups.h"
#include "app/commands.h"
#include "core/output_set.h"
#include "gl/context.h"
#include "scene/scene_io.h"

namespace ps {

namespace {

constexpr const char* kDescription =
    "Sweeps the accuracy knobs (reduction base resolution, probe depth-map size, Gabor impulses per\n"
    "kernel n, kernel truncation, Gabor evaluation strategy, displacement method) on an analytic\n"
    "scene (flat plane, orthographic camera, sphere probe 0.5 mm deep) and measures frame time and\n"
    "error against the CPU reference on the same frame. Also measures the skip ratios and the peak\n"
    "RSS of `pseudoshadow render` at 512x512 and 2048x2048. Takes a few minutes on 2 cores.";

struct BenchArgs {
  int size = 512, frames = 3;
  std::string out_dir = "bench_out";
  cli::GlArgs gl_opts;
  bool quiet = false;
  bool plot_only = false;  // draw the plots from --out-dir's bench.csv; no sweep, no GL
  bool first_image = false;  // time to the first image only (bench_first_image.h)
  int reps = 3;
  bool shadow_cost = false;  // only the pseudo-shadow's cost over plain shading; prints, writes nothing
  bool shadow_distance = false;  // only surface_normal against reference_plane distances; prints
  bool lut_cost = false;  // only the thesis formula against the same curve as a lookup table; prints
  bool texture_filter = false;  // only the Gabor texture's filtering: time vs error; prints
  bool moving = false;  // only frames while the view moves: whole against adaptive (bench_moving.h)
  bool quick = false;   // --moving: a few frames at 320x180, for the tests
  glm::ivec2 size_wh{0, 0};  // --size as given (any aspect): --moving's size; 0: its two sizes
};

// The measurements that replace the sweep, one flag each.
void declare_modes(CLI::App& app, BenchArgs& a) {
  app.add_flag("--first-image", a.first_image,
               "only time the first image as a user meets it: every shipped scene's one-frame `render` process "
               "and a 301-frame `replay`, under auto, naive and baked (CPU seconds, ratios; --out-dir gets "
               "first_image.md; about 10 minutes on 2 cores)");
  app.add_flag("--moving", a.moving,
               "only measure frames while the view moves (a camera orbit on the default scene, a travel "
               "through Field, a turn of the rolling flat torus) at 1280x720 and 1920x1080: whole frames against "
               "adaptive resolution in the same run, the scale used, the rest frame and the image error; --out-dir "
               "gets moving.md and moving.csv (a few minutes on 2 cores)");
  app.add_flag("--quick", a.quick, "--moving: 8 frames per case at 320x180 with a budget of 1 ms, so that they are reduced (a smoke test)");
  cli::add_int(app, "--reps", "N", a.reps, 1, 99,
               "--first-image: alternating runs per scene and strategy, the median is reported (default 3)");
  app.add_flag("--shadow-cost", a.shadow_cost,
               "only measure the pseudo-shadow frame of the default scene against the plain shading of the "
               "same view (probe out of reach) at 512x512 and 1024x1024, and print the table; writes no files");
  app.add_flag("--shadow-distance", a.shadow_distance,
               "only measure render.shadow_distance = surface_normal (closed form, and marched through the "
               "depth map) against reference_plane on the curved shipped scenes (Suzanne, the torus) at 512x512 "
               "and 1024x1024: frame times and how far each distance is off; prints the table, writes no files");
  app.add_flag("--lut-cost", a.lut_cost,
               "only measure the default scene's frame with its intensity curve read from a lookup table "
               "(textures/intensity_thesis.lut) against the formula at 512x512 and 1024x1024, and print the "
               "table; writes no files");
  app.add_flag("--texture-filter", a.texture_filter,
               "only measure the Gabor texture's filtering (gabor_filter = none / analytic, naive and baked) at "
               "--size, at most 256 (the reference renders 8x that per side), top-down and at a 15-degree grazing "
               "view: frame time against the error from an 8x8 supersampled reference; prints the table");
}

void declare(cli::Command& cmd, BenchArgs& a) {
  CLI::App& app = cmd.app();
  app.add_option_function<std::string>(
         "--size",
         [&a](const std::string& v) {
           // The sweep's analytic scene is square: WxH must have W == H (N is short for NxN).
           const glm::ivec2 sz = cli::parse_size(v, 2048, 2048LL * 2048);
           a.size_wh = sz;  // checked in run_and_report: --moving takes any aspect
           a.size = sz.x;
         },
         "image size for the sweep, square: NxN or N (default 512x512; 64..2048 per side); with --moving "
         "any WxH, in place of its 1280x720 and 1920x1080")
      ->type_name("WxH");
  cli::add_int(app, "--frames", "N", a.frames, 1, 1000,
               "timed warm frames per configuration and round (default 3); every configuration is measured "
               "in 3 round-robin rounds, the median over all its timed frames is reported");
  cli::add_gl_options(app, a.gl_opts);
  cli::add_output(app, "--out-dir", a.out_dir, "DIR",
                  "output directory (default bench_out): bench.csv, bench.md, bench.png, bench_ratios.png");
  app.add_flag("--plot-only", a.plot_only,
               "only draw bench.png and bench_ratios.png again from the bench.csv already in --out-dir "
               "(no sweep; needs gnuplot)")
      ->group(cli::kOutputGroup);
  declare_modes(app, a);
  cli::add_quiet_option(app, a.quiet);
}

// The sweep and the skip ratios, in this process's context (closed when they are done).
Status measure_in_process(const BenchArgs& a, const bench::BenchOptions& o, std::vector<bench::BenchRow>& rows,
                          bench::SkipRatios& skip) {
  auto ctx = cli::open_context(a.gl_opts, a.quiet);
  if (!ctx) return ctx.error();
  auto r = bench::run_sweep(o);
  if (!r) return r.error();
  rows = std::move(r.value());
  if (o.progress) o.progress("skip ratios ...");
  auto s = bench::run_skip_ratios(o);
  if (!s) return s.error();
  skip = s.value();
  return ok_status();
}

// The peak RSS of `render` at 512^2 and 2048^2, each in a process of its own.
Status measure_peak_rss(const BenchArgs& a, const bench::BenchOptions& o, bench::RssReport& rss) {
  const std::vector<std::string> gl_args = a.gl_opts.argv();
  for (int size : {512, 2048}) {
    if (o.progress) o.progress("peak RSS of render " + std::to_string(size) + "^2 ...");
    auto k = bench::render_peak_rss_kib(size, gl_args, a.out_dir);
    if (!k) return k.error();
    (size == 512 ? rss.kib_512 : rss.kib_2048) = k.value();
  }
  return ok_status();
}

Status run(const BenchArgs& a) {
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
  if (Status st = measure_in_process(a, o, rows, skip); !st) return st;
  bench::RssReport rss;
  if (Status st = measure_peak_rss(a, o, rss); !st) return st;
  const std::string md = bench::summary_markdown(rows, skip, rss, a.size);
  if (Status s = outputs.stage_text(csv, bench::csv_text(rows)); !s) return s;
  if (Status s = outputs.stage_text(md_path, md); !s) return s;
  if (Status s = outputs.publish(); !s) return s;
  if (!a.quiet) std::fputs(md.c_str(), stdout);
  if (Status s = bench::write_plots(a.out_dir, rows); !s)
    std::fprintf(stderr, "pseudoshadow bench: %s\n", s.error().message.c_str());
  return ok_status();
}

// The context and options of the printing-only measurements (--shadow-cost, --shadow-distance).
Result<std::unique_ptr<gl::Context>> bench_context(const BenchArgs& a, bench::BenchOptions& o) {
  o.timed_frames = a.frames;
  return cli::open_context(a.gl_opts, a.quiet);
}

// --shadow-cost: one measurement of the full bench, printed (about 20 s).
Status shadow_cost_only(const BenchArgs& a) {
  bench::BenchOptions o;
  auto ctx = bench_context(a, o);
  if (!ctx) return ctx.error();
  std::vector<bench::ShadowCost> costs;
  for (int size : {512, 1024}) {
    if (!a.quiet) std::fprintf(stderr, "pseudo-shadow cost at %d^2 ...\n", size);
    auto c = bench::run_shadow_cost(o, size);
    if (!c) return c.error();
    costs.push_back(c.value());
  }
  std::printf("| skip check | measured | target |\n| --- | --- | --- |\n%s\n%s",
              bench::shadow_cost_rows(costs).c_str(), bench::shadow_cost_table(costs).c_str());
  return ok_status();
}

// --lut-cost: the intensity curve read from a lookup table against the formula (about 20 s).
Status lut_cost_only(const BenchArgs& a) {
  bench::BenchOptions o;
  auto ctx = bench_context(a, o);
  if (!ctx) return ctx.error();
  std::printf("| size | frame, formula | frame, intensity_lut | ratio | surface pass ratio |\n| --- | --- | --- | --- | --- |\n");
  for (int size : {512, 1024}) {
    if (!a.quiet) std::fprintf(stderr, "lookup table cost at %d^2 ...\n", size);
    auto c = bench::run_lut_cost(o, default_scene_base_dir() + "/../textures/intensity_thesis.lut", size);
    if (!c) return c.error();
    std::printf("| %d^2 | %.2f ms | %.2f ms | %.3fx | %.3fx |\n", c->size, c->formula_frame_ms, c->lut_frame_ms, c->ratio,
                c->surface_ratio);
  }
  return ok_status();
}

// --shadow-distance: what the distance along each point's own normal costs and how far the
// thesis's single plane is off (about 1 min): the closed form (sphere/capsule probes) and the
// depth-map march (mesh probes) against the reference plane, at 512^2 and 1024^2.
Status shadow_distance_only(const BenchArgs& a) {
  bench::BenchOptions o;
  auto ctx = bench_context(a, o);
  if (!ctx) return ctx.error();
  std::printf("| scene | size | frame, reference_plane | frame, surface_normal | ratio | surface pass ratio "
              "| marched: frame, ratio | reference_plane off by (max / mean) | march off by (max / mean) |\n"
              "| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
  for (const int size : {512, 1024})
    for (const char* scene : {"table5_1_monkey_head.toml", "torus_capsule.toml"}) {
      if (!a.quiet) std::fprintf(stderr, "shadow distance on %s at %d^2 ...\n", scene, size);
      auto c = bench::run_distance_cost(o, default_scene_base_dir() + "/" + scene, size);
      if (!c) return c.error();
      std::printf("| %s | %d^2 | %.2f ms | %.2f ms | %.2fx | %.2fx | %.2f ms, %.2fx | %.3f / %.3f mm | %.3f / %.3f mm |\n",
                  c->scene.c_str(), c->size, c->plane_frame_ms, c->normal_frame_ms, c->ratio, c->surface_ratio,
                  c->marched_frame_ms, c->marched_ratio, c->plane_vs_normal_max_mm, c->plane_vs_normal_mean_mm,
                  c->marched_vs_normal_max_mm, c->marched_vs_normal_mean_mm);
    }
  return ok_status();
}

// --texture-filter: time vs error of the texture filter (about 30 s at 256^2).
Status texture_filter_only(const BenchArgs& a) {
  bench::BenchOptions o;
  auto ctx = bench_context(a, o);
  if (!ctx) return ctx.error();
  if (!a.quiet) o.progress = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); };
  auto table = bench::run_texture_filter(o, std::min(a.size, 256));
  if (!table) return table.error();
  std::fputs(table->c_str(), stdout);
  return ok_status();
}

// --plot-only: the plots are the whole job here, so a missing gnuplot is an error, not a warning.
Status plot_only(const BenchArgs& a) {
  const std::string csv = a.out_dir + "/bench.csv";
  const std::optional<std::string> text = read_whole_file(csv);
  if (!text) return make_error(csv + ": cannot read (--plot-only draws from the bench.csv of an earlier run)");
  auto rows = bench::parse_csv(*text, csv);
  if (!rows) return rows.error();
  if (Status s = bench::write_plots(a.out_dir, rows.value()); !s) return s;
  if (!a.quiet) std::fprintf(stderr, "wrote %s/bench.png and %s/bench_ratios.png\n", a.out_dir.c_str(), a.out_dir.c_str());
  return ok_status();
}

Status first_image(const BenchArgs& a) {
  OutputSet outputs;
  const std::string md_path = a.out_dir + "/first_image.md";
  if (Status s = outputs.add(md_path); !s) return s;
  bench::FirstImageOptions o;
  o.scenes_dir = default_scene_base_dir();
  o.work_dir = a.out_dir + "/first_image_work";
  o.gl_args = a.gl_opts.argv();
  o.reps = a.reps;
  if (!a.quiet) o.progress = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); };
  auto rows = bench::run_first_image(o);
  std::error_code ec;
  std::filesystem::remove_all(o.work_dir, ec);
  if (!rows) return rows.error();
  const std::string md = bench::first_image_markdown(rows.value(), a.reps);
  if (Status s = outputs.stage_text(md_path, md); !s) return s;
  if (Status s = outputs.publish(); !s) return s;
  if (!a.quiet) std::fputs(md.c_str(), stdout);
  return ok_status();
}

// --moving: whole against adaptive frames while the view moves (bench_moving.h).
Status moving(const BenchArgs& a) {
  OutputSet outputs;
  const std::string md_path = a.out_dir + "/moving.md", csv_path = a.out_dir + "/moving.csv";
  if (Status s = outputs.add(md_path); !s) return s;
  if (Status s = outputs.add(csv_path); !s) return s;
  bench::BenchOptions unused;
  auto ctx = bench_context(a, unused);
  if (!ctx) return ctx.error();
  bench::MovingOptions o;
  // Quick: a budget no frame meets, so that the reduced frames and the rest are exercised.
  if (a.quick) o.sizes = {{320, 180}}, o.frames = 8, o.error_every = 4, o.budget_ms = 1.0;
  if (a.size_wh.x > 0) o.sizes = {a.size_wh};
  if (!a.quiet) o.progress = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); };
  auto rows = bench::run_moving(o);
  if (!rows) return rows.error();
  const std::string md = bench::moving_markdown(rows.value(), o);
  if (Status s = outputs.stage_text(md_path, md); !s) return s;
  if (Status s = outputs.stage_text(csv_path, bench::moving_csv(rows.value())); !s) return s;
  if (Status s = outputs.publish(); !s) return s;
  if (!a.quiet) std::fputs(md.c_str(), stdout);
  return ok_status();
}

int run_and_report(const cli::Command& cmd, const BenchArgs& a) {
  const glm::ivec2 sz = a.size_wh;
  if (!a.moving && sz.x > 0 && (sz.x != sz.y || sz.x < 64))
    return cmd.usage_error(make_error("--size " + std::to_string(sz.x) + "x" + std::to_string(sz.y) +
                                      ": the sweep renders square images of 64 to 2048 pixels per side, e.g. "
                                      "--size 512x512 (or --size 512)"));
  const Status s = a.moving ? moving(a)
                   : a.plot_only     ? plot_only(a)
                   : a.first_image ? first_image(a)
                   : a.shadow_cost ? shadow_cost_only(a)
                   : a.shadow_distance ? shadow_distance_only(a)
                   : a.lut_cost ? lut_cost_only(a)
                   : a.texture_filter ? texture_filter_only(a)
                                   : run(a);
  return s ? cli::kExitOk : cmd.fail(s.error());
}

}  // namespace

int run_bench(int argc, char** argv) {
  return cli::run_command<BenchArgs>(argc, argv, "bench", kDescription, declare, run_and_report);
}

}  // namespace ps
