#include "app/study/study_experiment_cmd.h"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "app/cli/cli.h"
#include "app/cli/cli_groups.h"
#include "app/cli/stop_signal.h"
#include "app/study/study_window.h"
#include "core/file_io.h"
#include "study/experiment_scene.h"
#include "study/study_events.h"
#include "study/study_log.h"
#include "study/study_plan.h"
#include "study/study_run.h"
#include "study/study_summary.h"

namespace ps {

namespace {

// The experiment, read and its stimuli checked against the scene; a bad file is a usage error.
int load(const cli::Command& cmd, const std::string& path, study::Experiment& out) {
  Result<study::Experiment> e = study::load_experiment(path);
  if (!e) return cmd.usage_error(e.error());
  if (Status s = study::check_experiment_scene(e.value()); !s) return cmd.usage_error(s.error());
  out = std::move(e.value());
  return cli::kExitOk;
}

struct PlanArgs {
  std::string experiment, out;
  long long participants = 12;
};

void declare_plan(cli::Command& cmd, PlanArgs& a) {
  CLI::App& app = cmd.app();
  app.add_option("experiment", a.experiment, "the experiment file (e.g. scenes/studies/lambda_threshold.toml)")
      ->required()->type_name("EXPERIMENT");
  cli::add_int(app, "--participants", "N", a.participants, 1LL, 999LL, "participants to plan (default 12)");
  cli::add_output(app, "--out", a.out, "FILE", "writes the plan as CSV there (default: standard output)");
  cmd.usage("pseudoshadow study plan EXPERIMENT --participants N [--out plan.csv]");
}

int plan_main(const cli::Command& cmd, const PlanArgs& a) {
  study::Experiment e;
  if (int rc = load(cmd, a.experiment, e); rc != cli::kExitOk) return rc;
  const std::string csv = study::study_plan_csv(e, study::make_study_plan(e, static_cast<int>(a.participants)));
  if (a.out.empty()) {
    std::fputs(csv.c_str(), stdout);
    return cli::kExitOk;
  }
  if (Status s = write_file_atomic(a.out, csv); !s) return cmd.fail(s.error());
  return cli::kExitOk;
}

struct RunArgs {
  std::string experiment, participant, out, shape = "weibull", device = "mouse";
  bool simulate = false, quiet = false;
  double threshold = 0.1, slope = 3.0, lapse = 0.02, p_correct = 0.6;
  double fitts_a = 0.2, fitts_b = 0.15, mt_sd = 0.05, spread = 1.0;
  long long observer_seed = 0, stop_after = 0;
};

void declare_run(cli::Command& cmd, RunArgs& a) {
  CLI::App& app = cmd.app();
  app.add_option("experiment", a.experiment, "the experiment file")->required()->type_name("EXPERIMENT");
  app.add_option("--participant", a.participant, "the participant's ID, as `study plan` lists them (P01, ...)")
      ->required()->type_name("ID");
  app.add_option("--out", a.out, "the study's folder: the log goes to DIR/ID/trials.jsonl")->required()->type_name("DIR");
  app.add_flag("--simulate", a.simulate, "a simulated participant answers, headless (without it: a person, in a window)");
  cli::add_choice(app, "--device", "mouse|gamepad", a.device, {"mouse", "gamepad"}, "mouse",
                  "targeting in the window: what moves the probe (default mouse; gamepad: the left stick moves it, "
                  "the triggers lift and lower it)");
  cli::add_choice(app, "--shape", "weibull|logistic|normal", a.shape, {"weibull", "logistic", "normal"}, "weibull",
                  "the simulated participant's psychometric function (default weibull)");
  cli::add_positive(app, "--threshold", "ALPHA", a.threshold, 1e9, "0.1", "its threshold alpha, a difference (default 0.1)");
  cli::add_positive(app, "--slope", "BETA", a.slope, 1e9, "3", "its slope beta (default 3)");
  app.add_option("--lapse", a.lapse, "its lapse rate (default 0.02)")->check(CLI::Range(0.0, 0.49))->type_name("L");
  app.add_option("--p-correct", a.p_correct, "identification: its probability of naming the material shown (default 0.6)")
      ->check(CLI::Range(0.0, 1.0))->type_name("P");
  app.add_option("--fitts-a", a.fitts_a, "targeting: its Fitts intercept a, seconds (default 0.2)")
      ->check(CLI::Range(0.0, 60.0))->type_name("S");
  app.add_option("--fitts-b", a.fitts_b, "targeting: its Fitts slope b, seconds per bit (default 0.15)")
      ->check(CLI::Range(0.0, 60.0))->type_name("S");
  app.add_option("--mt-sd", a.mt_sd, "targeting: the SD of its movement times about a + b ID, seconds (default 0.05)")
      ->check(CLI::Range(0.0, 60.0))->type_name("S");
  cli::add_positive(app, "--spread", "K", a.spread, 100.0, "1",
                    "targeting: its end points' scatter, as the expected We / W (default 1: We = W, as ISO 9241-9 assumes)");
  cli::add_int(app, "--observer-seed", "N", a.observer_seed, 0LL, 9'007'199'254'740'991LL,
               "its answers' seed (default 0: the participant's seed)");
  cli::add_int(app, "--stop-after", "N", a.stop_after, 0LL, 1'000'000LL, "stop after N new trials (a break; run again to go on)");
  cli::add_quiet_option(app, a.quiet);
  cmd.usage("pseudoshadow study run EXPERIMENT --participant P01 --out DIR [--simulate [observer options]]");
  app.footer(std::string(cli::kExitStatusHelp) + " (0 also when Esc stops the window: `study resume` goes on)" +
             cli::kExitSignalHelp);
}

// "pseudoshadow study resume EXPERIMENT --participant P01 --out DIR": how a stopped run goes on.
std::string resume_command(const RunArgs& a) {
  return "pseudoshadow study resume " + a.experiment + " --participant " + a.participant + " --out " + a.out;
}

// Whether a participant's log has ended (its last line session_end): then there is nothing to
// open a window for, and run_participant says the log is complete. A log that does not read is
// left to run_participant's message.
bool ended(const std::string& log_path) {
  if (!std::filesystem::exists(log_path)) return false;
  const Result<study::TrialLog> log = study::read_trial_log(log_path);
  return log && !log->lines.empty() && log->lines.back().json.value("type", "") == "session_end";
}

int run_main(const cli::Command& cmd, const RunArgs& a) {
  if (Result<int> id = study::participant_index(a.participant); !id) return cmd.usage_error(id.error());
  study::Experiment e;
  if (int rc = load(cmd, a.experiment, e); rc != cli::kExitOk) return rc;
  study::RunSpec spec;
  spec.participant = a.participant;
  spec.out_dir = a.out;
  spec.stop_after = static_cast<int>(a.stop_after);
  spec.resume_only = cmd.name() == "study resume";
  spec.observer.shape = a.shape == "logistic" ? study::Shape::kLogistic
                        : a.shape == "normal" ? study::Shape::kCumulativeNormal
                                              : study::Shape::kWeibull;
  spec.observer.truth = {a.threshold, a.slope, 0.5, a.lapse};
  spec.observer.p_correct = a.p_correct;
  spec.observer.seed = static_cast<std::uint64_t>(a.observer_seed);
  spec.observer.pointer.a_s = a.fitts_a;
  spec.observer.pointer.b_s_per_bit = a.fitts_b;
  spec.observer.pointer.mt_sd_s = a.mt_sd;
  spec.observer.pointer.spread = a.spread;
  // Without --simulate a person answers in the window (docs/study.md, "In the window").
  const cli::StopSignals stop;  // SIGTERM, SIGINT, SIGHUP: the run ends as Esc ends it
  std::unique_ptr<StudyWindow> window;
  if (!a.simulate && !ended(a.out + "/" + a.participant + "/trials.jsonl")) {
    StudyWindowParams params{stop.predicate(), {}};
    params.device.kind = a.device == "gamepad" ? DeviceKind::kGamepad : DeviceKind::kMouse;
    Result<std::unique_ptr<StudyWindow>> w = StudyWindow::open(e, std::move(params));
    if (!w) return cmd.fail(w.error());
    window = std::move(w.value());
    spec.responder = window.get();
  }
  Result<study::RunReport> r = study::run_participant(e, spec);
  window.reset();  // the window closes before the lines below
  if (!r) return cmd.fail(r.error());
  if (r->stopped) {
    const int logged = r->done_before + r->written;
    if (stop.requested()) {
      std::fprintf(stderr, "%s\n",
                   cli::stop_line("study", stop, "trial log", r->log_path, "resume with: " + resume_command(a)).c_str());
      return stop.exit_code();
    }
    std::fprintf(stderr, "study: stopped after %d of %d trials; the log is %s; resume with: %s\n", logged, r->total,
                 r->log_path.c_str(), resume_command(a).c_str());
    return cli::kExitOk;
  }
  if (!r->torn.empty()) std::fprintf(stderr, "pseudoshadow %s: warning: %s\n", cmd.name().c_str(), r->torn.c_str());
  if (!a.quiet)
    std::printf("%s: %d of %d trials logged (%d before this run, %d now)%s\n", r->log_path.c_str(),
                r->done_before + r->written, r->total, r->done_before, r->written, r->complete ? ", complete" : "");
  return cli::kExitOk;
}

struct SummarizeArgs {
  std::vector<std::string> logs;
  std::string out;
  long long resamples = 1000, seed = 1;
  bool quiet = false;
};

void declare_summarize(cli::Command& cmd, SummarizeArgs& a) {
  CLI::App& app = cmd.app();
  app.add_option("logs", a.logs, "trial logs, participants' folders or a study's folder (the --out of `study run`)")
      ->required()->type_name("LOG|DIR");
  app.add_option("--out", a.out, "writes participants.csv, groups.csv, summary.md and the plot there (events.tsv go beside each log)")
      ->required()->type_name("DIR");
  cli::add_int(app, "--resamples", "N", a.resamples, 10LL, 1000000LL, "bootstrap resamples (default 1000)");
  cli::add_int(app, "--seed", "N", a.seed, 0LL, 9'007'199'254'740'991LL, "the bootstrap's seed (default 1)");
  cli::add_quiet_option(app, a.quiet);
  cmd.usage("pseudoshadow study summarize LOG|DIR... --out DIR");
}

int summarize_main(const cli::Command& cmd, const SummarizeArgs& a) {
  Result<std::vector<std::string>> logs = study::find_trial_logs(a.logs);
  if (!logs) return cmd.fail(logs.error());
  std::vector<study::ParticipantResult> people;
  std::vector<study::TrialLog> read;  // each log read and checked once: for its fit, then its events
  std::vector<std::string> notes;
  for (const std::string& log : logs.value()) {
    Result<study::TrialLog> lines = study::read_trial_log(log);
    if (!lines) return cmd.fail(lines.error());
    Result<study::ParticipantResult> p = study::summarize_participant(
        lines.value(), log, {static_cast<int>(a.resamples), static_cast<std::uint64_t>(a.seed)});
    if (!p) return cmd.fail(p.error());
    if (!people.empty() && (p->experiment != people[0].experiment || p->task != people[0].task))
      return cmd.usage_error(make_error(log + ": of experiment '" + p->experiment + "', not '" + people[0].experiment +
                                        "': summarize one experiment at a time"));
    for (const study::ParticipantResult& q : people)
      if (q.participant == p->participant)
        return cmd.usage_error(make_error(log + ": participant " + p->participant + " is also in " + q.log +
                                          ": give each participant once"));
    if (!p->torn.empty()) notes.push_back(p->torn);
    people.push_back(std::move(p.value()));
    read.push_back(std::move(lines.value()));
  }
  // Each ended session's events.tsv and sidecar, beside its log, from the log just checked; a
  // session not ended (or cut off) gets none, with a note.
  for (std::size_t i = 0; i < people.size(); ++i) {
    const study::ParticipantResult& p = people[i];
    if (!p.complete || !p.torn.empty()) {
      notes.push_back(p.participant + ": no events.tsv written: the session has not ended (resume it, then summarize again)");
      continue;
    }
    if (Result<study::EventsFiles> f = study::write_session_events(read[i], p.log); !f) return cmd.fail(f.error());
  }
  if (Status s = study::write_study_summary(a.out, people, notes); !s) return cmd.fail(s.error());
  for (const std::string& n : notes) std::fprintf(stderr, "pseudoshadow %s: %s\n", cmd.name().c_str(), n.c_str());
  if (!a.quiet) std::printf("summarized %zu participant%s into %s\n", people.size(), people.size() == 1 ? "" : "s", a.out.c_str());
  return cli::kExitOk;
}

constexpr const char* kPlanDescription =
    "Each participant's ID, seed and condition order (a balanced Latin square of the experiment's conditions)\n"
    "as CSV (docs/study.md, \"Planning\").";
constexpr const char* kRunDescription =
    "One participant through an experiment: a person in a window, answering with the keys (docs/study.md,\n"
    "\"In the window\"), or with --simulate a simulated participant, headless. Each trial is appended to\n"
    "DIR/ID/trials.jsonl with its SHA-256 and fsync'd. Run again on the same DIR (or use `study resume`),\n"
    "it goes on after the last whole trial (docs/study.md, \"Running\").";
constexpr const char* kSummarizeDescription =
    "Checks every trial log's checksums, fits each participant and condition (threshold, slope, 95 % bootstrap\n"
    "and credible intervals, Weber fraction; or the confusion matrix and information transfer; or the\n"
    "Fitts statistics) and writes the tables, summary.md and a plot (docs/study.md, \"Summarizing\");\n"
    "beside each ended session's log, its BIDS-style sub-ID_task-NAME_events.tsv and .json (docs/study.md,\n"
    "\"events.tsv (BIDS)\").";

}  // namespace

int run_study_experiment(int argc, char** argv) {
  const std::string_view sub = argv[0];
  if (sub == "plan")
    return cli::run_command<PlanArgs>(argc, argv, "study plan", kPlanDescription, declare_plan, plan_main);
  if (sub == "run" || sub == "resume")
    return cli::run_command<RunArgs>(argc, argv, "study " + std::string(sub), kRunDescription, declare_run, run_main);
  if (sub == "summarize")
    return cli::run_command<SummarizeArgs>(argc, argv, "study summarize", kSummarizeDescription, declare_summarize,
                                           summarize_main);
  return -1;
}

}  // namespace ps
