// Time source of the haptic loop. SteadyClock is the real one (std::chrono::steady_clock);
// FakeClock jumps instantly to every wake-up time, so tests and `replay` run the very same
// scheduling code deterministically and as fast as the CPU allows.
#pragma once

#include <algorithm>
#include <chrono>
#include <thread>

namespace ps {

class Clock {
 public:
  using Ns = std::chrono::nanoseconds;  // since an arbitrary epoch
  virtual ~Clock() = default;
  virtual Ns now() = 0;
  virtual void sleep_until(Ns when) = 0;
};

class SteadyClock final : public Clock {
 public:
  Ns now() override { return std::chrono::steady_clock::now().time_since_epoch(); }
  void sleep_until(Ns when) override {
    std::this_thread::sleep_until(std::chrono::steady_clock::time_point(when));
  }
};

// Single-threaded use only (tests, replay).
class FakeClock final : public Clock {
 public:
  Ns now() override { return now_; }
  void sleep_until(Ns when) override { now_ = std::max(now_, when); }
  void advance(Ns by) { now_ += by; }

 private:
  Ns now_{0};
};

}  // namespace ps
