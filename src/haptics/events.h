// Events of the haptic world: contact start and end, a button firing, a body hitting the floor,
// a charge added or removed, a scene switch, a flag toggled. They feed the sound (docs/sound.md)
// and the JSON-lines event log of `run` and `replay`.
// Who produces what:
//   the haptic thread pushes into HapticLoop::events(), an EventQueue: single producer, single
//   consumer, fixed capacity, never allocates after construction (a full queue drops the event
//   and counts it); the render thread (or `replay`, between run_ticks calls) drains it;
//   the render thread's own events (a charge added with a key) skip the queue.
// Times are session times of the haptic tick (seconds), so a replay is deterministic.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace ps {

enum class EventKind : std::uint8_t {
  contact_start,   // value: approach speed, mm/s (the normal speed into the surface, >= 0)
  contact_end,
  button_fired,    // index: button; label: its action
  body_impact,     // index: body; value: impact speed, mm/s
  charge_added,    // index: charge; value: its charge
  charge_removed,  // index: charge
  scene_switched,  // label: the new scene file
  flag_toggled,    // label: the flag's name; value: its new state (0 or 1)
  sheet_crossing,  // value: +1 passing in front of another sheet, -1 behind it (4D worlds)
  tick_stall,      // the loop woke late (haptics/tick_schedule.h); value: ms late; index: ticks skipped
};

// "contact_start", ... (the JSON "event" field); "unknown" outside the enum.
std::string_view event_name(EventKind kind);

struct HapticEvent {
  EventKind kind = EventKind::contact_start;
  std::uint64_t tick = 0;
  double time_s = 0.0;
  int surface = -1;  // Scene::surfaces index, -1 when none
  int index = -1;    // button / body / charge index, -1 when none
  double value = 0.0;
  glm::dvec3 position_mm{0.0};
  std::array<char, 48> label{};  // NUL-terminated, truncated; fixed size: no allocation on push

  void set_label(std::string_view s);
  std::string_view label_view() const;
};

// An event of `kind` raised at tick `tick`, session time `time_s`; the rest as defaulted above.
HapticEvent make_event(EventKind kind, std::uint64_t tick, double time_s);

// One JSON object on one line, no trailing newline; fields in a fixed order, doubles with 17
// significant digits (a replay's log compares byte for byte):
// {"t":0.25,"tick":250,"event":"contact_start","surface":0,"index":-1,"value":12.5,"pos":[0,0,8],"label":""}
std::string event_json(const HapticEvent& e);

class EventQueue {
 public:
  explicit EventQueue(std::size_t capacity = 1024);
  EventQueue(const EventQueue&) = delete;
  EventQueue& operator=(const EventQueue&) = delete;

  bool push(const HapticEvent& e);  // producer; false (and counted) when full
  // Consumer: calls f(event) for each queued event in push order; returns how many.
  template <class F>
  std::size_t drain(F&& f) {
    std::size_t n = 0;
    std::size_t tail = tail_.load(std::memory_order_relaxed);
    const std::size_t head = head_.load(std::memory_order_acquire);
    for (; tail != head; ++tail, ++n) f(static_cast<const HapticEvent&>(ring_[tail % ring_.size()]));
    tail_.store(tail, std::memory_order_release);
    return n;
  }
  std::uint64_t dropped() const { return dropped_.load(std::memory_order_relaxed); }
  std::size_t capacity() const { return ring_.size(); }

 private:
  std::vector<HapticEvent> ring_;
  std::atomic<std::size_t> head_{0}, tail_{0};  // monotonically increasing; index = % size
  std::atomic<std::uint64_t> dropped_{0};
};

}  // namespace ps
