// `pseudoshadow calibrate`: measures just-noticeable differences along a material's distance ->
// intensity or speed -> gain curve with interleaved 1-up-2-down staircases (calibrate/
// calibration.h) and writes the lookup table that makes equal steps look equally different
// (docs/calibrate.md). A person answers in the window (app/calibrate/calibrate_window.cpp); with
// --observer simulated a scripted observer with a known psychometric function answers, headless.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/calibrate/calibrate_window.h"
#include "app/cli/cli.h"
#include "app/cli/cli_groups.h"
#include "app/cli/stop_signal.h"
#include "app/commands.h"
#include "core/file_io.h"
#include "reference/modulation.h"

namespace ps {

namespace {

using calibrate::CurveKind;

constexpr const char* kDescription =
    "Two-alternative forced choice (thesis §5.2): two pseudo-shadows side by side, \"which is closer?\"\n"
    "(--curve distance) or \"which texture is moving faster?\" (--curve speed); answer with the Left or\n"
    "Right arrow key (Esc stops; the trials so far are kept). One 1-up-2-down staircase per reference\n"
    "point, interleaved at random, finds the difference answered right 70.7 % of the time (the JND).\n"
    "Then the curve is remapped so every JND-sized step looks alike: S(x) = integral of 1/JND, the new\n"
    "table shows at x what the material's curve showed at S^-1(S(range) x / range); its ends keep\n"
    "the curve's range, and beyond --range it follows the curve. Writes the table (--out, format:\n"
    "docs/scene-format.md \"Lookup tables\"; use it as materials.NAME.intensity_lut or speed_gain_lut)\n"
    "and the trial log (CSV), each written to a temp file and renamed. --observer simulated runs\n"
    "headless: an observer with JND J(q) = JND + WEBER q in the shown quantity q (intensity or gain)\n"
    "answers right with probability Phi(0.545 |q_a - q_b| / J) (docs/calibrate.md).";

struct CalibrateArgs {
  cli::SceneArgs scene;
  std::string material, curve, references, out, log, observer = "human", resume;
  double range = 0.0, observer_jnd = 0.01, observer_weber = 0.1;
  long long seed = 1, reversals = 16, average_last = 12;
  bool quiet = false, window = false;
};

void declare(cli::Command& cmd, CalibrateArgs& a) {
  CLI::App& app = cmd.app();
  cli::add_scene_options(app, a.scene);
  app.add_option("--material", a.material, "the material whose curve is calibrated (default: the scene's first)")
      ->type_name("NAME");
  cli::add_choice(app, "--curve", "distance|speed", a.curve, {"distance", "speed"}, "distance",
                  "distance: distance -> intensity (\"which pseudo-shadow is closer?\"); speed: speed -> texture gain "
                  "(\"which texture is moving faster?\") (required)");
  app.add_option("--references", a.references,
                 "reference points, increasing, mm or mm/s (default distance 1,2,4,8; speed 0.2,0.4,0.6,0.8 x the "
                 "speed where the material's gain first peaks, peak_hz x lambda_min)")
      ->type_name("X,Y,...");
  cli::add_positive(app, "--range", "MAX", a.range, 1e5, "10",
                    "the table is equalised over [0, MAX] (default: 1.25 x the last reference for distance, the "
                    "gain's first peak for speed)");
  cli::add_choice(app, "--observer", "human|simulated", a.observer, {"human", "simulated"}, "simulated",
                  "human (default): a window, answers from the arrow keys; simulated: the scripted observer, headless");
  cli::add_positive(app, "--observer-jnd", "J", a.observer_jnd, 1.0, "0.01",
                    "simulated observer: its JND in the shown quantity at 0 (default 0.01)");
  cli::add_positive(app, "--observer-weber", "W", a.observer_weber, 10.0, "0.1",
                    "simulated observer: its Weber fraction (default 0.1)");
  app.add_flag("--window", a.window,
               "with --observer simulated: show the trials in the window while the simulated observer answers "
               "(the same trials, log and table as headless)");
  cli::add_int(app, "--seed", "N", a.seed, 0LL, 9'007'199'254'740'991LL,
               "order of the trials, sides, and the simulated observer's answers (default 1)");
  cli::add_int(app, "--reversals", "N", a.reversals, 2LL, 1000LL, "reversals per staircase before it ends (default 16)");
  cli::add_int(app, "--average-last", "N", a.average_last, 1LL, 1000LL,
               "JND: geometric mean of the differences at the last N reversals (default 12)");
  cli::add_output(app, "--out", a.out, "FILE.lut", "the lookup table to write (required)");
  cli::add_output(app, "--log", a.log, "FILE.csv",
                  "the trial log, CSV (default: FILE.lut's name + .trials.csv)");
  app.add_option("--resume", a.resume,
                 "continue a calibration stopped early (Esc, a crash) from its trial log: give the same options and "
                 "--seed as that run; its answers are replayed, the rest is asked, and the log gets every trial")
      ->type_name("LOG.csv");
  cli::add_quiet_option(app, a.quiet);
  cmd.usage("pseudoshadow calibrate --curve distance|speed --out FILE.lut [--observer simulated] [options]");
  app.footer(std::string(cli::kExitStatusHelp) + cli::kExitSignalHelp);
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

Result<std::vector<double>> parse_references(const std::string& text) {
  std::vector<double> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    const double v = cli::parse_positive("--references", item, 1e5, "1,2,4,8");
    if (!out.empty() && v <= out.back())
      return make_error("--references: expected increasing values, e.g. --references 1,2,4,8 (got '" + text + "')");
    out.push_back(v);
  }
  if (out.empty()) return make_error("--references: expected at least one value, e.g. --references 1,2,4,8");
  return out;
}

// The curve the staircases run on, and the speed where the gain first peaks.
calibrate::CurveFn shown_curve(const Material& m, CurveKind kind) {
  if (kind == CurveKind::kDistance) return [m](double d) { return intensity_curve(m, d); };
  return [m](double v) { return amplitude_gain(m, v); };
}

// The material named by --material (default the scene's first); null when there is none.
const Material* find_material(const Scene& scene, const std::string& name) {
  if (name.empty()) return scene.materials.empty() ? nullptr : &scene.materials.front();
  for (const Material& m : scene.materials)
    if (m.name == name) return &m;
  return nullptr;
}

// The staircases' spec from the options: references and range (defaults per curve), steps.
Result<calibrate::Spec> make_spec(const CalibrateArgs& a, const Material& m, double& range) {
  calibrate::Spec spec;
  spec.kind = a.curve == "distance" ? CurveKind::kDistance : CurveKind::kSpeed;
  const double first_peak = m.peak_hz * std::min(m.gabor.lambda_min_mm, m.gabor.lambda_max_mm);
  spec.references = spec.kind == CurveKind::kDistance
                        ? std::vector<double>{1.0, 2.0, 4.0, 8.0}
                        : std::vector<double>{0.2 * first_peak, 0.4 * first_peak, 0.6 * first_peak, 0.8 * first_peak};
  if (!a.references.empty()) {
    auto r = parse_references(a.references);
    if (!r) return r.error();
    spec.references = r.value();
  }
  const double last = spec.references.back();
  range = a.range > 0.0 ? a.range : spec.kind == CurveKind::kDistance ? 1.25 * last : first_peak;
  if (range <= last)
    return make_error("--range (" + number(range) + ") must exceed the last reference (" + number(last) +
                      "), e.g. --range " + number(1.25 * last));
  spec.seed = static_cast<std::uint64_t>(a.seed);
  spec.staircase.start_delta = 0.25 * spec.references.front() + 0.05 * range;
  spec.staircase.max_delta = range;
  spec.staircase.reversals = static_cast<int>(a.reversals);
  spec.staircase.average_last = static_cast<int>(a.average_last);
  return spec;
}

// The equalising table from the staircases that finished (all of them, unless the person stopped
// early), with the JNDs in its comments (and on stdout unless quiet).
Status write_table(const CalibrateArgs& a, const calibrate::Calibration& cal, const Material& m,
                   const calibrate::CurveFn& shown, double range) {
  const calibrate::Spec& spec = cal.spec();
  const bool distance = spec.kind == CurveKind::kDistance;
  const std::vector<double> all = cal.jnds();
  const std::vector<bool> finished = cal.finished();
  std::vector<double> refs, jnds;
  for (std::size_t i = 0; i < all.size(); ++i)
    if (finished[i]) refs.push_back(spec.references[i]), jnds.push_back(all[i]);
  const Lut lut = calibrate::equalising_lut(spec.kind, shown, refs, jnds, range, distance ? m.influence_distance_mm : 4.0 * range);
  std::vector<std::string> comments = {"pseudoshadow calibrate --curve " + a.curve + ", material " + m.name + ", " +
                                       std::to_string(cal.trials().size()) + " trials, observer " + a.observer};
  const std::string unit = distance ? "mm" : "mm/s";
  for (std::size_t i = 0; i < all.size(); ++i) {
    comments.push_back("JND at " + number(spec.references[i]) + " " + unit + ": " + number(all[i]) + " " + unit + " (" +
                       std::to_string(cal.reversals()[i]) + " reversals)" + (finished[i] ? "" : ", not finished: not used"));
    if (!a.quiet) std::printf("%s\n", comments.back().c_str());
  }
  comments.push_back("equal steps over [0, " + number(range) + "] " + unit + "; the material's curve beyond");
  if (Status s = write_lut(a.out, lut, comments); !s) return s;
  if (!a.quiet) std::printf("calibrate: %zu trials; table %s (%zu rows)\n", cal.trials().size(), a.out.c_str(), lut.points.size());
  return ok_status();
}

// --resume LOG: the log's answers again, in order (a simulated observer draws its answers as
// it did, so the rest goes on as the uninterrupted run would).
Status resume_from(const std::string& path, calibrate::Calibration& cal, calibrate::SimulatedObserver* observer) {
  const std::optional<std::string> text = read_whole_file(path);
  if (!text) return make_error(path + ": cannot open the trial log to resume (the .trials.csv a stopped run wrote)");
  auto answers = calibrate::parse_trial_log(*text, path);
  if (!answers) return answers.error();
  for (std::size_t i = 0; i < answers->size(); ++i) {
    if (observer && !cal.done()) observer->answer_left(cal.current(), cal.spec().kind);
    if (Status s = calibrate::replay_answer(cal, (*answers)[i], path + ":" + std::to_string(i + 2)); !s) return s;
  }
  return ok_status();
}

// The trials still to run (none after a finished --resume): by the simulated observer, or in
// the window (answered by the simulated observer's script, or by the person).
// `stop`: a signal asked to stop (app/cli/stop_signal.h); the trials end as Esc ends them.
Status collect_answers(const CalibrateArgs& a, calibrate::Calibration& cal, calibrate::SimulatedObserver& observer,
                       const Scene& scene, const Material& m, const std::string& log_path,
                       const std::function<bool()>& stop) {
  const bool simulated = a.observer == "simulated";
  if (cal.done()) return ok_status();
  if (simulated && !a.window) {
    calibrate::run_simulated(cal, observer, stop);
    return ok_status();
  }
  CalibrateWindowParams wp{scene, m, log_path, {}, stop};
  const calibrate::CurveKind kind = cal.spec().kind;
  if (simulated) wp.script = [&observer, kind](const calibrate::Trial& t) { return observer.answer_left(t, kind); };
  return run_calibrate_window(cal, wp);
}

// Stopped before every staircase finished: says how to continue; false when none finished (then
// there is no table to write).
bool report_stopped(const calibrate::Calibration& cal, const std::string& log_path) {
  const std::vector<bool> finished = cal.finished();
  std::printf("calibrate: stopped after %zu trials (%zu of %zu staircases finished); trials in %s; continue with "
              "--resume %s\n",
              cal.trials().size(), static_cast<std::size_t>(std::count(finished.begin(), finished.end(), true)),
              finished.size(), log_path.c_str(), log_path.c_str());
  if (std::count(finished.begin(), finished.end(), true) == 0) {
    std::printf("calibrate: no staircase finished: no table written\n");
    return false;
  }
  return true;
}

// After a signal: where the trials are and the command line that goes on from them; 128 + the
// signal's number.
int report_signal(const cli::Command& cmd, const cli::StopSignals& stop, const std::string& log_path) {
  const std::string next = "resume with: " + cli::command_with(cmd.name(), cmd.args(), "--resume", log_path);
  std::fprintf(stderr, "%s\n", cli::stop_line("calibrate", stop, "trial log", log_path, next).c_str());
  return stop.exit_code();
}

int calibrate_main(const cli::Command& cmd, const CalibrateArgs& a) {
  if (a.curve.empty() || a.out.empty())
    return cmd.usage_error(make_error("--curve and --out are required (e.g. --curve distance --out textures/mine.lut)"));
  auto scene = cli::load_scene_or_default(a.scene);
  if (!scene) return cmd.fail(scene.error(), cli::scene_exit_code(scene.error()));
  const Material* m = find_material(scene.value(), a.material);
  if (!m) return cmd.usage_error(make_error("--material: the scene has no material '" + a.material + "'"));
  double range = 0.0;
  auto spec = make_spec(a, *m, range);
  if (!spec) return cmd.usage_error(spec.error());
  const std::string log_path = a.log.empty() ? std::filesystem::path(a.out).replace_extension(".trials.csv").string() : a.log;
  for (const std::string& p : {a.out, log_path})
    if (Status s = prepare_output_dir(p); !s) return cmd.fail(s.error());

  const calibrate::CurveFn shown = shown_curve(*m, spec->kind);
  calibrate::Calibration cal(spec.value());
  calibrate::SimulatedObserver observer(shown, {a.observer_jnd, a.observer_weber, static_cast<std::uint64_t>(a.seed) + 1});
  const bool simulated = a.observer == "simulated";
  if (!a.resume.empty())
    if (Status s = resume_from(a.resume, cal, simulated ? &observer : nullptr); !s) return cmd.fail(s.error());
  const cli::StopSignals stop;  // SIGTERM, SIGINT, SIGHUP: the trials end as Esc ends them
  if (Status s = collect_answers(a, cal, observer, scene.value(), *m, log_path, stop.predicate()); !s)
    return cmd.fail(s.error());
  if (Status s = write_file_atomic(log_path, calibrate::format_trial_log(cal)); !s) return cmd.fail(s.error());
  // The signal's line comes last, after what was written.
  const auto done = [&] { return stop.requested() ? report_signal(cmd, stop, log_path) : cli::kExitOk; };
  if (!cal.done() && !report_stopped(cal, log_path)) return done();
  if (Status s = write_table(a, cal, *m, shown, range); !s) return cmd.fail(s.error());
  if (!a.quiet) std::printf("calibrate: trials %s\n", log_path.c_str());
  return done();
}

}  // namespace

int run_calibrate(int argc, char** argv) {
  return cli::run_command<CalibrateArgs>(argc, argv, "calibrate", kDescription, declare, calibrate_main);
}

}  // namespace ps
