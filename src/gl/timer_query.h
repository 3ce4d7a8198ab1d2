// Per-pass GPU times from GL_TIME_ELAPSED queries, double-buffered so the CPU never waits: a
// frame's queries are read when their results are available (checked with
// GL_QUERY_RESULT_AVAILABLE), at the latest when the frame after next begins, and a result
// that has not come back by then is dropped, not waited for.
//
// Usage per frame: begin_frame(); lap("pass") after each pass; end_frame(). results() is the
// newest frame whose every query has come back; lag() says how many frames ago that was.
// Needs a current GL 4.5 context for every call; render thread only.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "gl/gl.h"

namespace ps::gl {

class TimerQueries {
 public:
  using Timings = std::vector<std::pair<std::string, double>>;  // pass name, ms

  TimerQueries() = default;
  ~TimerQueries();
  TimerQueries(const TimerQueries&) = delete;
  TimerQueries& operator=(const TimerQueries&) = delete;

  void begin_frame();
  void lap(const char* name);  // ends the running query as pass `name`, starts the next one
  // Ends the frame's last (unnamed) query and takes its results if they are already there.
  void end_frame();
  // Takes any finished frame's results; wait = true blocks until the last frame's are there
  // (for a one-shot command after its last frame, whose image is read back anyway).
  void poll(bool wait = false);

  const Timings& results() const { return results_; }
  // Frames between the newest begun frame and results(); -1: none yet.
  int lag() const { return results_frame_ < 0 ? -1 : static_cast<int>(frame_ - results_frame_); }

 private:
  struct Slot {
    std::vector<GLuint> queries;   // grows to the most passes a frame had; reused
    std::vector<std::string> names;
    bool pending = false;          // ended, results not read yet
    long long frame = -1;
  };
  bool collect(Slot& slot, bool wait);
  void start_query();

  Slot slots_[2];
  int current_ = 1;
  bool open_ = false;  // a query of the current slot is running
  long long frame_ = -1;
  Timings results_;
  long long results_frame_ = -1;
};

}  // namespace ps::gl
