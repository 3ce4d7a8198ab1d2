// `pseudoshadow maze summarize`: session logs (maze_log.h) into tables per participant and per
// group (condition), as CSV and markdown, and two plots (errors per room by condition, time per
// trial), in the spirit of the comparison of the two groups in Sepulveda-Cervantes et al. §VII.
// Reading and the numbers need no gnuplot; only write_plots() does.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/result.h"
#include "maze/maze.h"

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
  bool ended = false;            // the log has its session_end line (else the session was cut short)
  std::string end_reason;        // criterion, max_passes, device_ended, quit ("" when cut short)
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
  bool aborted() const { return !ended || (end_reason != "criterion" && end_reason != "max_passes"); }
  // The end-reason column: "crashed" for a log cut short (no session_end after the last resume).
  std::string end_reason_or_crashed() const { return ended ? end_reason : "crashed"; }
  double mean_room_time_s(int cue) const {
    return trials[static_cast<std::size_t>(cue)] > 0 ? room_time_s[static_cast<std::size_t>(cue)] / trials[static_cast<std::size_t>(cue)] : 0.0;
  }
};

// A mean and its 95 % confidence interval's half width (Student's t, n - 1 degrees of freedom;
// NaN for n < 2).
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
  double mean_trials_to_criterion = 0.0;  // over those who reached it
  double mean_total_time_s = 0.0;
  std::array<double, kCueCount> mean_errors{};     // per participant
  std::array<double, kCueCount> mean_room_time_s{};  // mean of the participants' means
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

// One log; errors name file:line (a line that is not JSON, a missing session_start).
Result<ParticipantSummary> summarize_log(const std::string& path);
// Groups by condition and session, in order of first appearance. Aborted sessions
// (ParticipantSummary::aborted) are counted in `excluded` and left out of the means unless
// include_aborted.
std::vector<GroupSummary> summarize_groups(const std::vector<ParticipantSummary>& people, bool include_aborted = false);
std::vector<RetestSummary> summarize_retests(const std::vector<ParticipantSummary>& people);

// participants.csv, groups.csv, trials.csv, rooms.csv, retest.csv and summary.md in `dir` (which must exist).
Status write_tables(const std::string& dir, const std::vector<ParticipantSummary>& people,
                    const std::vector<GroupSummary>& groups, const std::vector<RetestSummary>& retests);
// errors_by_room.png and time_per_trial.png (gnuplot).
Status write_plots(const std::string& dir, const std::vector<ParticipantSummary>& people,
                   const std::vector<GroupSummary>& groups);

}  // namespace ps::maze
