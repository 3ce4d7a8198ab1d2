// `pseudoshadow maze summarize`: session logs (maze_log.h) into tables per participant and per
// group (condition), as CSV and markdown, and two plots (errors per room by condition, time per
// trial), in the spirit of the comparison of the two groups in Sepulveda-Cervantes et al. §VII.
// Reading and the numbers need no gnuplot; only write_plots() does. A mean over nobody (N = 0:
// every session of a group aborted, a room no one left) is NaN here, an empty cell in the CSV
// files and "—" in summary.md; a plot with nothing to draw is skipped with a note (plan_plots),
// never left empty.
#pragma once

#include <array>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "core/result.h"
#include "maze/maze.h"
#include "maze/maze_log.h"

namespace ps::maze {

inline constexpr int kCueCount = 6;  // Cue::kNone ... Cue::kExternalForce

// One room of one pass, from its branch line (rooms.csv).
struct RoomTrial {
  int pass = 0, room = 0;           // from 1
  std::string cue, exit;            // exit: left, straight, right ("" in a log without it)
  bool correct = false;
  double time_s = 0.0, path_mm = 0.0;
  std::array<int, 4> contacts{};    // floor, wall, ceiling, hidden: contacts begun
};

struct ParticipantSummary {
  std::string participant, condition, log;
  int session = 1;               // 1, or a retest (logs without the field: 1)
  std::uint64_t seed = 0;
  // Which run of the participant's session this is (check_no_duplicates): session_start's
  // `started_at` (wall clock, UTC; "" in a log written before the field) and the whole line.
  std::string started_at, start_line;
  std::string torn;              // a warning: the log's last line was cut off and left out
  bool ended = false;            // the log has its session_end line (else the session was cut short)
  EndReason end_reason = EndReason::kQuit;  // session_end's reason (when ended)
  int resumed = 0;               // `resumed` lines: the session was interrupted and went on (maze --resume)
  int passes = 0;                // complete passes
  int trials_to_criterion = 0;   // the perfect pass (from 1); 0: not reached
  double total_time_s = 0.0;     // session time of the last line
  std::array<int, kCueCount> trials{};        // rooms passed (branches), per cue
  std::array<int, kCueCount> errors{};        // wrong exits, per cue
  std::array<double, kCueCount> room_time_s{};  // summed time in the room, per cue
  std::vector<double> pass_time_s;            // per complete pass: first room entered to last left
  std::vector<int> pass_correct;              // per complete pass
  std::vector<RoomTrial> rooms;               // every room left, in order
  // Ended by neither the criterion nor max_passes (quit, device_ended, crashed): left out of the
  // group means unless asked for (summarize_groups).
  bool aborted() const { return !ended || !completes_session(end_reason); }
  // The end-reason column: "crashed" for a log cut short (no session_end after the last resume).
  std::string end_reason_or_crashed() const { return ended ? end_reason_name(end_reason) : "crashed"; }
  // NaN when the room was never left (no trial of that cue).
  double mean_room_time_s(int cue) const;
};

// A mean (NaN for n = 0) and its 95 % confidence interval's half width (Student's t, n - 1
// degrees of freedom; NaN for n < 2).
struct MeanCi {
  double mean = 0.0, half = 0.0;
  int n = 0;
};
MeanCi mean_ci(const std::vector<double>& values);

struct GroupSummary {  // one condition in one session (1: the first; 2: the retest; ...)
  std::string condition;
  int session = 1;
  int excluded = 0;  // aborted sessions left out of every mean below
  int participants = 0, reached_criterion = 0;
  // NaN: no one to average (N = 0, or no one reached the criterion / left that room).
  double mean_trials_to_criterion = 0.0;  // over those who reached it
  double mean_total_time_s = 0.0;
  std::array<double, kCueCount> mean_errors{};     // per participant
  std::array<double, kCueCount> mean_room_time_s{};  // mean of the means of those who left the room
  std::vector<double> mean_pass_time_s;            // per pass index, over those who made that pass
  double ci_total_time_s = 0.0;                    // 95 % CI half widths of the means above
  std::array<double, kCueCount> ci_errors{};
  std::vector<double> ci_pass_time_s;
  std::vector<int> pass_n;                         // participants who made each pass
};

// The retest of Sepulveda-Cervantes et al. §VII: per condition, of the participants with a complete
// first session and a complete session 2, how many took less time in session 2.
struct RetestSummary {
  std::string condition;
  int retested = 0, faster = 0;
  double share_faster() const { return retested > 0 ? static_cast<double>(faster) / retested : 0.0; }
};

// `maze summarize`'s arguments as session logs, in order. A file is a log. A folder holding a
// session.jsonl is a participant's (what `maze --out DIR` writes): that log. Any other folder is
// a study folder: the session.jsonl of each of its subfolders, in name order (DIR/practice/ is
// never taken: practice is not part of the study). A folder with no log there gets a line in
// `notes` and adds nothing. Errors: a path that does not exist.
Result<std::vector<std::string>> find_session_logs(const std::vector<std::string>& args, std::vector<std::string>& notes);
// One log; errors name file:line (a line that is not JSON, a missing session_start).
Result<ParticipantSummary> summarize_log(const std::string& path);
// An error naming both logs when two of `people` are one session given twice (the same
// participant, session and started_at; for logs without it, the same session_start line): it
// would count twice in every mean.
Status check_no_duplicates(const std::vector<ParticipantSummary>& people);
// Groups by condition and session, in order of first appearance. Aborted sessions
// (ParticipantSummary::aborted) are counted in `excluded` and left out of the means unless
// include_aborted.
std::vector<GroupSummary> summarize_groups(const std::vector<ParticipantSummary>& people, bool include_aborted = false);
std::vector<RetestSummary> summarize_retests(const std::vector<ParticipantSummary>& people);

// Lines for a person: a group with nobody in its means (N = 0) and why. summarize prints them and
// summary.md lists them with the skipped plots.
std::vector<std::string> group_notes(const std::vector<GroupSummary>& groups);

// participants.csv, groups.csv, trials.csv, rooms.csv, retest.csv and summary.md in `dir` (which
// must exist); `notes` (group_notes, skipped plots) go into summary.md's Notes.
Status write_tables(const std::string& dir, const std::vector<ParticipantSummary>& people,
                    const std::vector<GroupSummary>& groups, const std::vector<RetestSummary>& retests,
                    const std::vector<std::string>& notes = {});

// One of summarize's plots: drawn, or skipped with the reason ("no completed trials").
struct PlotPlan {
  enum class Kind { kErrorsByRoom, kTimePerTrial } kind;
  std::string file;     // errors_by_room.png, time_per_trial.png
  std::string skipped;  // empty: it has something to draw
  std::string note() const { return file + " skipped: " + skipped; }
};
std::vector<PlotPlan> plan_plots(const std::vector<ParticipantSummary>& people, const std::vector<GroupSummary>& groups);
// The plots plan_plots() does not skip (gnuplot), each drawn to FILE.partial and renamed to FILE
// when gnuplot succeeded and wrote something; a failed one leaves nothing at either name. Each
// plot's gnuplot script stays beside it (FILE without .png + .gp).
Status write_plots(const std::string& dir, const std::vector<ParticipantSummary>& people,
                   const std::vector<GroupSummary>& groups);

// One plot: `script` writes a gnuplot script drawing to the PNG path it is given; the script is
// kept as dir/STEM.gp, the plot drawn to dir/png_name + ".partial" and renamed to dir/png_name
// when gnuplot succeeded and wrote something; on any failure nothing is left at either name.
// Shared with `study summarize`.
Status draw_plot(const std::string& dir, const std::string& png_name,
                 const std::function<void(std::ostringstream&, const std::string&)>& script);

}  // namespace ps::maze
