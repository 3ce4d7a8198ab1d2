// `maze --resume DIR` (docs/maze.md, "Sessions that survive"): where an interrupted session
// stands, read back from its own log. The log is line-atomic (maze_log.h), so whatever killed
// the process left whole lines; the session goes on at the next unfinished trial with the same
// seed, condition and room orders, at the session time of the last room left (a room entered
// but not left is walked again). No GL, no I/O besides reading the log.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/result.h"
#include "maze/maze_log.h"
#include "maze/maze_track.h"

namespace ps::maze {

struct ResumePoint {
  SessionInfo info;                // from session_start (device: as the first run gave it)
  std::vector<std::array<Cue, 5>> planned;  // a study plan's room orders (Route::planned)
  std::vector<PassScore> done;     // passes with their pass_end line
  PassScore current;               // the pass in progress: its rooms left so far
  bool current_started = false;    // its pass_start line is in the log
  double time_s = 0.0;             // session time of the last room left (or pass start): where it goes on
  int resumes = 0;                 // `resumed` lines already in the log
  std::optional<EndReason> ended;  // a session_end's reason already in the log (none: open)
  std::string torn;                // a warning: the log's last line was cut off and left out
};

// Reads DIR's session log. Errors name file:line; a session that ended by the criterion or
// max_passes has nothing to resume.
Result<ResumePoint> read_resume_point(const std::string& log_path);

// Where the probe waits at r.time_s: the hall of the last room left (the start corridor before
// any), 1 mm over the floor; a live hand is put there (a log device is asked where it is).
glm::dvec3 resume_place(const MazeDesc& desc, const ResumePoint& r);

}  // namespace ps::maze
