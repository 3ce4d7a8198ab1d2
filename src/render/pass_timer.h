// CPU wall time per pass (glFinish between passes) and, where `gpu` is given, GPU time per pass
// from timer queries (no wait; gl/timer_query.h), into a frame's stats. One per frame.
#pragma once

#include <chrono>

#include "gl/timer_query.h"
#include "render/frame_stats.h"

namespace ps {

class PassTimer {
 public:
  PassTimer(bool enabled, FrameStats& stats, gl::TimerQueries* gpu) : enabled_(enabled), stats_(stats), gpu_(gpu) {
    restart();
    if (gpu_ != nullptr) gpu_->begin_frame();
  }
  ~PassTimer() {
    if (gpu_ == nullptr) return;
    gpu_->end_frame();
    stats_.gpu_timings_ms = gpu_->results();
    stats_.gpu_timings_lag = gpu_->lag();
  }
  PassTimer(const PassTimer&) = delete;
  PassTimer& operator=(const PassTimer&) = delete;
  void lap(const char* name) {
    if (gpu_ != nullptr) gpu_->lap(name);
    if (!enabled_) return;
    glFinish();  // llvmpipe renders on flush: finishing makes the wall time the pass's time
    const auto now = std::chrono::steady_clock::now();
    stats_.timings_ms.emplace_back(name, std::chrono::duration<double, std::milli>(now - start_).count());
    start_ = now;
  }
  void restart() {
    if (enabled_) glFinish();
    start_ = std::chrono::steady_clock::now();
  }

 private:
  bool enabled_;
  FrameStats& stats_;
  gl::TimerQueries* gpu_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace ps
