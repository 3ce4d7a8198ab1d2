// `pseudoshadow tune`: headless parameter tuning: sweeps rendered into one labelled contact
// sheet, or a scripted console session read from stdin (docs/tuning.md).
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <unistd.h>

#include "app/cli/cli.h"
#include "app/cli/cli_groups.h"
#include "app/commands.h"
#include "core/output_set.h"
#include "gl/context.h"
#include "tune/console.h"
#include "tune/overrides_file.h"
#include "tune/sweep.h"
#include "tune/sweep_shard.h"

namespace ps {

namespace {

constexpr const char* kConsoleHelp = R"(Console (--console): commands from stdin, one per line: set KEY VALUE, render [N],
save FILE(.png|.exr|.toml), stats, reload, help, quit, # comment. Errors name the line and the
session continues; the exit status is 1 if any command failed.
)";

constexpr const char* kDescription =
    "Sweeps: renders the cross product of the sweeps (one render per cell, exactly as `render`\n"
    "with --set KEY=VALUE) into one contact sheet, each cell labelled with its values.";

struct TuneArgs {
  cli::SceneArgs scene;
  cli::GlArgs gl_opts;
  std::string out, csv, out_dir;
  std::vector<SweepAxis> axes;
  std::string shard_text;              // --shard I/N
  ShardSpec shard;
  std::vector<std::string> merge;      // --merge DIR...
  bool console = false, quiet = false;
};

// The sweep's axes and its sharding: --sweep, --sweep-scenes, --shard, --merge.
void declare_sweep_options(CLI::App& app, TuneArgs& a) {
  auto axis = [&a](Result<SweepAxis> parsed) {
    if (!parsed) throw cli::UsageError(parsed.error().message);
    a.axes.push_back(std::move(parsed.value()));
  };
  cli::add_ordered(app, "--sweep", "KEY=V1,V2,...",
                   "a sweep axis: listed values (TOML values; [..] arrays allowed), or KEY=FROM:TO:STEPS, "
                   "STEPS evenly spaced numbers, FROM and TO included (STEPS >= 2)",
                   [axis](const std::string& v) { axis(parse_sweep(v)); });
  cli::add_ordered(app, "--sweep-scenes", "A,B,...",
                   "a sweep axis over scene files (labelled by file name); at most 256 cells in all; the "
                   "last axis runs along a row",
                   [axis](const std::string& v) { axis(parse_scene_sweep(v)); });
  app.add_option_function<std::string>(
         "--shard",
         [&a](const std::string& v) {
           auto shard = parse_shard(v);
           if (!shard) throw cli::UsageError(shard.error().message);
           a.shard = shard.value();
           a.shard_text = v;
         },
         "render only shard I of N of the sweep's cells (every N-th, from cell I-1) into --out-dir, "
                 "for machines that render in parallel; `--merge` assembles the sheet")
      ->type_name("I/N");
  app.add_option("--merge", a.merge, "assemble the sheet (--out) and CSV (--csv) from these --shard directories")
      ->type_name("DIR...")
      ->expected(1, -1);
}

void declare(cli::Command& cmd, TuneArgs& a) {
  CLI::App& app = cmd.app();
  cli::add_scene_options(app, a.scene);
  cli::add_probe_options(app, a.scene);
  cli::add_image_options(app, a.scene);
  declare_sweep_options(app, a);
  app.add_flag("--console", a.console, "run a scripted console session read from stdin (below)");
  cli::add_gl_options(app, a.gl_opts);
  cli::add_output(app, "--out", a.out, "SHEET.png", "the contact sheet (required for sweeps)");
  cli::add_output(app, "--out-dir", a.out_dir, "DIR",
                  "a shard's directory (with --shard): cell_NNNN.png and shard.json");
  app.add_option("--csv", a.csv, std::string("per-cell values and frame stats. ") + cli::kOutputRule)->type_name("FILE")->group(cli::kOutputGroup);
  cli::add_quiet_option(app, a.quiet);
  cmd.usage("pseudoshadow tune --scene FILE --sweep KEY=V1,V2,... [...] --out SHEET.png\n"
            "       pseudoshadow tune --scene FILE --sweep ... --shard I/N --out-dir DIR\n"
            "       pseudoshadow tune --merge DIR... --out SHEET.png [--csv FILE]\n"
            "       pseudoshadow tune --console [--scene FILE] < session.txt");
  app.footer(std::string(kConsoleHelp) + cli::kExitStatusHelp);
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

// The sheet and CSV of a whole sweep (rendered here, or merged from shards), published together.
int write_sheet(const cli::Command& cmd, const TuneArgs& a, OutputSet& outputs, const std::vector<SweepAxis>& axes,
                const std::vector<SweepCell>& cells) {
  auto fail = [&cmd](const Error& e) { return cmd.fail(e, 1); };
  const Image sheet = sweep_sheet(axes, cells);
  if (Status s = stage_image(outputs, a.out, sheet); !s) return fail(s.error());
  if (!a.csv.empty())
    if (Status s = outputs.stage_text(a.csv, sweep_csv(axes, cells)); !s) return fail(s.error());
  if (Status s = outputs.publish(); !s) return fail(s.error());
  if (!a.quiet) std::printf("wrote %s (%zu cells, %dx%d)\n", a.out.c_str(), cells.size(), sheet.width, sheet.height);
  return 0;
}

int run_merge(const cli::Command& cmd, const TuneArgs& a) {
  OutputSet outputs;
  if (Status s = outputs.add(a.out); !s) return cmd.fail(s.error(), 1);
  if (!a.csv.empty())
    if (Status s = outputs.add(a.csv); !s) return cmd.fail(s.error(), 1);
  auto merged = merge_shards(a.merge);
  if (!merged) return cmd.fail(merged.error(), 1);
  return write_sheet(cmd, a, outputs, merged->axes, merged->cells);
}

int run_shard(const cli::Command& cmd, const TuneArgs& a) {
  OutputSet outputs;
  if (Status s = outputs.add(a.out_dir + "/shard.json"); !s) return cmd.fail(s.error(), 1);
  SweepJob job{a.scene.path, a.scene.lines(), a.axes, {}, a.shard, a.scene.allow_paths};
  const bool tty = isatty(STDERR_FILENO);
  auto cells = render_sweep(job, [&](std::size_t done, std::size_t total, const std::string& label) {
    if (!a.quiet) print_progress(done, total, label, tty);
  });
  if (!cells) return cmd.fail(cells.error(), 1);
  const std::size_t total = sweep_cell_count(a.axes).value();
  if (Status s = stage_shard(outputs, a.out_dir, a.axes, total, a.shard, cells.value()); !s) return cmd.fail(s.error(), 1);
  if (Status s = outputs.publish(); !s) return cmd.fail(s.error(), 1);
  if (!a.quiet)
    std::printf("wrote shard %zu/%zu to %s (%zu of %zu cells)\n", a.shard.index, a.shard.count, a.out_dir.c_str(),
                cells->size(), total);
  return 0;
}

int run_sweep(const cli::Command& cmd, const TuneArgs& a) {
  auto fail = [&cmd](const Error& e, int code) { return cmd.fail(e, code); };
  // Both outputs checked before the sweep and published together after it (or neither).
  OutputSet outputs;
  if (Status s = outputs.add(a.out); !s) return fail(s.error(), 1);
  if (!a.csv.empty())
    if (Status s = outputs.add(a.csv); !s) return fail(s.error(), 1);
  SweepJob job{a.scene.path, a.scene.lines(), a.axes, {}, {}, a.scene.allow_paths};
  const bool tty = isatty(STDERR_FILENO);
  auto cells = render_sweep(job, [&](std::size_t done, std::size_t total, const std::string& label) {
    if (!a.quiet) print_progress(done, total, label, tty);
  });
  if (!cells) return fail(cells.error(), 1);
  return write_sheet(cmd, a, outputs, a.axes, cells.value());
}

int run_console_mode(const cli::Command& cmd, const TuneArgs& a, Scene scene) {
  auto session = TuneSession::open({a.scene.path, a.scene.lines(), {}, a.scene.allow_paths, {}}, std::move(scene));
  if (!session) return cmd.fail(session.error());
  const ConsoleResult r = run_console(*session.value(), std::cin, std::cout, std::cerr);
  return r.errors == 0 ? 0 : 1;
}

int tune(const cli::Command& cmd, const TuneArgs& a) {
  const auto usage = [&cmd](const std::string& m) { return cmd.usage_error(make_error(m)); };
  if (!a.merge.empty()) {
    if (!a.axes.empty() || a.console || !a.shard_text.empty())
      return usage("--merge assembles shards already rendered: give it without --sweep, --shard or --console");
    if (a.out.empty()) return usage("--out SHEET.png is required with --merge");
    return run_merge(cmd, a);
  }
  if (!a.shard_text.empty()) {
    if (a.axes.empty() || a.console) return usage("--shard splits a sweep: give it with --sweep (not --console)");
    if (a.out_dir.empty()) return usage("--out-dir DIR is required with --shard (the shard's cells go there)");
    if (!a.out.empty() || !a.csv.empty())
      return usage("a shard writes --out-dir only; draw the sheet with --merge DIR... --out SHEET.png");
  } else if (!a.out_dir.empty()) {
    return usage("--out-dir is for --shard; a whole sweep writes --out SHEET.png");
  }
  if (a.console && !a.axes.empty()) return usage("--console and --sweep cannot be combined");
  if (!a.console && a.axes.empty()) return usage("nothing to do: give --sweep KEY=... (and --out SHEET.png) or --console");
  if (!a.console && a.out.empty() && a.shard_text.empty()) return usage("--out SHEET.png is required for a sweep");
  if (auto n = sweep_cell_count(a.axes); !n) return cmd.usage_error(n.error());
  // Validate before creating the context: bad keys and values fail fast. The base scene first,
  // so a bad --set (or --velocity, ...) is blamed on its own option; then every sweep cell.
  const bool scene_axis = std::any_of(a.axes.begin(), a.axes.end(), [](const SweepAxis& x) { return x.key == kSceneAxisKey; });
  auto scene = scene_axis ? Result<Scene>(Scene{}) : cli::load_scene_or_default(a.scene);
  if (!scene) return cmd.fail(scene.error(), cli::scene_exit_code(scene.error()));
  if (!a.console)
    if (Status s = validate_sweep({a.scene.path, a.scene.lines(), a.axes, {}, {}, a.scene.allow_paths}); !s)
      return cmd.fail(s.error(), cli::scene_exit_code(s.error()));
  auto ctx = cli::open_context(a.gl_opts);
  if (!ctx) return cmd.fail(ctx.error());
  if (a.console) return run_console_mode(cmd, a, std::move(scene.value()));
  return a.shard_text.empty() ? run_sweep(cmd, a) : run_shard(cmd, a);
}

}  // namespace

int run_tune(int argc, char** argv) {
  return cli::run_command<TuneArgs>(argc, argv, "tune", kDescription, declare, tune);
}

}  // namespace ps
