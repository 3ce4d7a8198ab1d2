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
  // Real clocks: sleep until `spin` before each wake-up, then poll the clock up to it (the
  // kernel's wake-up is late by up to the timer slack plus the scheduling latency; the last
  // stretch polled is on time if the thread still has its core). No-op for the fake clock.
  virtual void set_wake_spin(Ns /*spin*/) {}
};

class SteadyClock final : public Clock {
 public:
  Ns now() override { return std::chrono::steady_clock::now().time_since_epoch(); }
  void sleep_until(Ns when) override {
    if (spin_.count() <= 0) {
      std::this_thread::sleep_until(std::chrono::steady_clock::time_point(when));
      return;
    }
    const Ns wake = when - spin_;
    if (now() < wake) std::this_thread::sleep_until(std::chrono::steady_clock::time_point(wake));
    while (now() < when) {
#if defined(__x86_64__) || defined(__i386__)
      __builtin_ia32_pause();
#endif
    }
  }
  void set_wake_spin(Ns spin) override { spin_ = spin; }

 private:
  Ns spin_{0};
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
