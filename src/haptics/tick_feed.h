// Every tick of the haptic loop as a small record, for consumers that need each tick rather than
// the latest state (the vibration signal, src/vibration/: it follows the proxy's path tick by
// tick; the maze window's tracker: it must see every room the proxy passes through however slow
// the frames are). HapticLoop::add_tick_feed() (before start) makes the haptic thread push one
// TickSample per tick into each feed given (at most kMaxTickFeeds); one consumer drains each. Single producer, single consumer, fixed capacity, never
// allocates after construction; a full feed drops the tick and counts it (the consumer then
// sees a gap in `tick` and starts its path afresh).
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace ps {

struct TickSample {
  std::uint64_t tick = 0;
  double time_s = 0.0;            // session time of the tick
  std::int64_t clock_ns = 0;      // the loop clock's time at the tick (steady_clock live)
  glm::dvec3 proxy_mm{0.0};       // the proxy (world), on the surface in contact
  glm::dvec3 velocity_mm_s{0.0};  // the hand's filtered velocity (world)
  glm::dvec3 normal{0.0, 0.0, 1.0};  // contact normal, unit (out of the surface); meaningful in contact
  double normal_force_n = 0.0;    // the force's component along `normal`, >= 0
  int surface = -1;               // Scene::surfaces index touched, -1 out of contact
  bool in_contact = false;
  double impact_mm_s = 0.0;       // > 0 on the tick a contact starts: the approach speed
  bool click = false;             // a scene button fired on this tick
  // For a consumer that follows the proxy itself (the maze's tracker, maze/maze_session.h):
  glm::dvec3 proxy_centre_mm{0.0};  // the proxy's centre (world), HapticState::proxy_mm
  glm::dvec3 force_n{0.0};          // the tick's whole force on the hand (world), HapticState::force_n
  glm::dvec3 field_force_n{0.0};    // its part from fields and navigation, HapticState::field_force_n
};

class TickFeed {
 public:
  explicit TickFeed(std::size_t capacity = 4096) : ring_(capacity) {}
  TickFeed(const TickFeed&) = delete;
  TickFeed& operator=(const TickFeed&) = delete;

  // Producer (the haptic thread). False (and counted) when full.
  bool push(const TickSample& s) {
    const std::size_t head = head_.load(std::memory_order_relaxed);
    // acquire: the consumer's reads of the slots it released happen before we overwrite them
    if (head - tail_.load(std::memory_order_acquire) >= ring_.size()) {
      dropped_.fetch_add(1, std::memory_order_relaxed);
      return false;
    }
    ring_[head % ring_.size()] = s;
    head_.store(head + 1, std::memory_order_release);  // publishes the slot written above
    return true;
  }
  // Consumer: f(sample) for each queued tick in order; returns how many.
  template <class F>
  std::size_t drain(F&& f) {
    std::size_t tail = tail_.load(std::memory_order_relaxed);
    const std::size_t head = head_.load(std::memory_order_acquire);  // pairs with push's release
    std::size_t n = 0;
    for (; tail != head; ++tail, ++n) f(static_cast<const TickSample&>(ring_[tail % ring_.size()]));
    tail_.store(tail, std::memory_order_release);
    return n;
  }
  std::uint64_t dropped() const { return dropped_.load(std::memory_order_relaxed); }

 private:
  std::vector<TickSample> ring_;
  std::atomic<std::size_t> head_{0}, tail_{0};  // monotonically increasing; index = % size
  std::atomic<std::uint64_t> dropped_{0};
};

}  // namespace ps
