// `pseudoshadow maze summarize`: session logs (maze_log.h) into tables per participant and per
// group (condition), as CSV and markdown, and two plots (errors per room by condition, time per
// trial), in the spirit of seed 003 §VII's comparison of the two groups. Reading and the
// numbers need no gnuplot; only write_plots() does.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/result.h"
#include "maze/maze.h"

namespace ps::maze {

inline constexpr int kCueCount = 6;  // Cue::kNone ... Cue::kExternalForce

struct ParticipantSummary {
  std::string participant, condition, log;
  int session = 1;               // 1, or a retest (logs without the field: 1)
  std::uint64_t seed = 0;
  bool ended = false;            // the log has its session_end line (else the session was cut short)
  std::string end_reason;        // criterion, max_passes, device_ended, quit ("" when cut short)
  int passes = 0;                // complete passes
  int trials_to_criterion = 0;   // the perfect pass (from 1); 0: not reached
  double total_time_s = 0.0;     // session time of the last line
  std::array<int, kCueCount> trials{};        // rooms passed (branches), per cue
  std::array<int, kCueCount> errors{};        // wrong exits, per cue
  std::array<double, kCueCount> room_time_s{};  // summed time in the room, per cue
  std::vector<double> pass_time_s;            // per complete pass: first room entered to last left
  std::vector<int> pass_correct;              // per complete pass
  double mean_room_time_s(int cue) const {
    return trials[static_cast<std::size_t>(cue)] > 0 ? room_time_s[static_cast<std::size_t>(cue)] / trials[static_cast<std::size_t>(cue)] : 0.0;
  }
};

struct GroupSummary {  // one condition in one session (1: the first; 2: the retest; ...)
  std::string condition;
  int session = 1;
  int participants = 0, reached_criterion = 0;
  double mean_trials_to_criterion = 0.0;  // over those who reached it
  double mean_total_time_s = 0.0;
  std::array<double, kCueCount> mean_errors{};     // per participant
  std::array<double, kCueCount> mean_room_time_s{};  // mean of the participants' means
  std::vector<double> mean_pass_time_s;            // per pass index, over those who made that pass
};

// Seed 003 §VII's retest: per condition, of the participants with a complete first session
// and a complete session 2, how many took less time in session 2.
struct RetestSummary {
  std::string condition;
  int retested = 0, faster = 0;
  double share_faster() const { return retested > 0 ? static_cast<double>(faster) / retested : 0.0; }
};

// One log; errors name file:line (a line that is not JSON, a missing session_start).
Result<ParticipantSummary> summarize_log(const std::string& path);
// Groups by condition and session, in order of first appearance.
std::vector<GroupSummary> summarize_groups(const std::vector<ParticipantSummary>& people);
std::vector<RetestSummary> summarize_retests(const std::vector<ParticipantSummary>& people);

// participants.csv, groups.csv, trials.csv, retest.csv and summary.md in `dir` (which must exist).
Status write_tables(const std::string& dir, const std::vector<ParticipantSummary>& people,
                    const std::vector<GroupSummary>& groups, const std::vector<RetestSummary>& retests);
// errors_by_room.png and time_per_trial.png (gnuplot).
Status write_plots(const std::string& dir, const std::vector<ParticipantSummary>& people,
                   const std::vector<GroupSummary>& groups);

}  // namespace ps::maze
