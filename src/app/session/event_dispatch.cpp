#include "app/session/event_dispatch.h"

#include <cassert>

namespace ps {

void EventDispatcher::subscribe(std::string name, Handler handler) {
  assert(handler && "EventDispatcher::subscribe: empty handler");
  subscribers_.push_back({std::move(name), std::move(handler)});
}

void EventDispatcher::dispatch(const HapticEvent& e) {
  ++dispatched_;
  for (const Subscriber& s : subscribers_) s.handler(e);
}

std::size_t EventDispatcher::pump(EventQueue& queue) {
  return queue.drain([this](const HapticEvent& e) { dispatch(e); });
}

}  // namespace ps
