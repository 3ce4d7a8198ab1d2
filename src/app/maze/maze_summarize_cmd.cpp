#include "app/maze/maze_summarize_cmd.h"

#include <cstdio>

#include "app/cli/cli.h"
#include "app/cli/cli_groups.h"
#include "core/file_io.h"
#include "maze/maze_summary.h"

namespace ps {

namespace {

struct SummarizeArgs {
  std::vector<std::string> logs;
  std::string out_dir;
  bool no_plots = false, quiet = false, include_aborted = false;
};

void declare_summarize(cli::Command& cmd, SummarizeArgs& a) {
  CLI::App& app = cmd.app();
  app.add_option("logs", a.logs,
                 "session logs (DIR/session.jsonl), participants' folders (DIR: its session.jsonl) or a study folder "
                 "(each subfolder's session.jsonl)")
      ->type_name("LOG|DIR");
  cli::add_output(app, "--out", a.out_dir, "DIR",
                  "writes participants.csv, groups.csv, trials.csv, rooms.csv, summary.md and the plots there (required); it "
                  "must exist, or only its last component may be missing (it is created)");
  app.add_flag("--no-plots", a.no_plots, "tables only (no gnuplot needed)");
  app.add_flag("--include-aborted", a.include_aborted,
               "count aborted sessions (quit, device_ended, terminated, crashed) in the group means too (default: "
               "left out, counted in groups.csv's `excluded`)");
  cli::add_quiet_option(app, a.quiet);
  cmd.usage("pseudoshadow maze summarize LOG|DIR... --out DIR");
}

// Every log the arguments name, read; a session given twice is a usage error (exit 2).
int read_people(const cli::Command& cmd, const SummarizeArgs& a, std::vector<maze::ParticipantSummary>& people,
                std::vector<std::string>& notes) {
  auto logs = maze::find_session_logs(a.logs, notes);
  if (!logs) return cmd.fail(logs.error());
  for (const std::string& log : logs.value()) {
    auto p = maze::summarize_log(log);
    if (!p) return cmd.fail(p.error());
    if (!p->torn.empty()) notes.push_back(p->torn);  // printed with the other notes
    people.push_back(std::move(p.value()));
  }
  if (Status s = maze::check_no_duplicates(people); !s) return cmd.usage_error(s.error());
  return cli::kExitOk;
}

// "summarized 3 sessions (2 in the group means) in 2 groups into DIR".
void print_done(const SummarizeArgs& a, const std::vector<maze::ParticipantSummary>& people,
                const std::vector<maze::GroupSummary>& groups) {
  int in_means = 0;
  for (const maze::GroupSummary& g : groups) in_means += g.participants;
  std::printf("summarized %zu session%s (%d in the group means) in %zu group%s into %s\n", people.size(),
              people.size() == 1 ? "" : "s", in_means, groups.size(), groups.size() == 1 ? "" : "s", a.out_dir.c_str());
}

int summarize_main(const cli::Command& cmd, const SummarizeArgs& a) {
  if (a.logs.empty() || a.out_dir.empty())
    return cmd.usage_error(make_error("give at least one log or folder and --out DIR (e.g. maze summarize study/P01 "
                                      "study/P02 --out summary)"));
  std::vector<maze::ParticipantSummary> people;
  std::vector<std::string> notes;
  if (int rc = read_people(cmd, a, people, notes); rc != cli::kExitOk) return rc;
  const auto groups = maze::summarize_groups(people, a.include_aborted);
  for (const std::string& n : maze::group_notes(groups)) notes.push_back(n);
  if (!a.no_plots)
    for (const maze::PlotPlan& p : maze::plan_plots(people, groups))
      if (!p.skipped.empty()) notes.push_back(p.note());
  if (Status s = prepare_output_dir(a.out_dir + "/summary.md"); !s) return cmd.fail(s.error());
  if (Status s = maze::write_tables(a.out_dir, people, groups, maze::summarize_retests(people), notes); !s)
    return cmd.fail(s.error());
  if (!a.no_plots)
    if (Status s = maze::write_plots(a.out_dir, people, groups); !s) return cmd.fail(s.error());
  // Notes on stderr, even with -q: each says what is missing from the outputs and why.
  for (const std::string& n : notes) std::fprintf(stderr, "pseudoshadow maze summarize: %s\n", n.c_str());
  if (!a.quiet) print_done(a, people, groups);
  return cli::kExitOk;
}

}  // namespace

int run_maze_summarize(int argc, char** argv) {
  return cli::run_command<SummarizeArgs>(argc, argv, "maze summarize",
                                         "Tables (CSV, markdown) and plots (PNG) of maze session logs, per "
                                         "participant and per condition (docs/maze.md).",
                                         declare_summarize, summarize_main);
}

}  // namespace ps
