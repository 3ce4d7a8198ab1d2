// The one place a session drains the haptic events and fans them out (docs/sound.md, "Event
// dispatch"). HapticLoop::events() is single-consumer: `run` calls pump() once per frame on the
// render thread (`replay` calls dispatch() for each event it drains between frames), and every
// part that acts on events subscribes here instead of draining the queue itself:
//
//   EventDispatcher events;
//   events.subscribe("log", [&](const HapticEvent& e) { log.append(e); });
//   events.subscribe("switch", [&](const HapticEvent& e) {
//     if (e.kind == EventKind::scene_switched) ...;
//   });
//   ... each frame: events.pump(loop.events());
//
// Subscribers run on the pumping thread, in subscription order, for each event in push (= time)
// order; they must not block (the render thread calls them). Render-thread events (a charge
// added with a key) go through dispatch() directly.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "haptics/events.h"

namespace ps {

class EventDispatcher {
 public:
  using Handler = std::function<void(const HapticEvent&)>;

  void subscribe(std::string name, Handler handler);  // name: for messages and tests
  std::size_t subscribers() const { return subscribers_.size(); }

  void dispatch(const HapticEvent& e);  // every subscriber, in subscription order
  std::size_t pump(EventQueue& queue);  // drain the queue through dispatch(); how many events
  std::uint64_t dispatched() const { return dispatched_; }

 private:
  struct Subscriber {
    std::string name;
    Handler handler;
  };
  std::vector<Subscriber> subscribers_;
  std::uint64_t dispatched_ = 0;
};

}  // namespace ps
