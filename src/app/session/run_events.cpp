#include "app/session/run_events.h"

namespace ps {

Result<std::unique_ptr<RunEvents>> RunEvents::open(const RunEventsDesc& desc) {
  std::unique_ptr<RunEvents> r(new RunEvents);
  if (!desc.log_path.empty()) {
    auto log = EventLog::open(desc.log_path);
    if (!log) return log.error();
    r->log_ = std::move(log.value());
    EventLog* l = r->log_.get();
    r->dispatcher_.subscribe("event log", [l](const HapticEvent& e) { l->append(e); });
  }
  r->audio_ = audio::LiveAudio::open(desc.audio);
  if (r->audio_->active()) {
    audio::LiveAudio* a = r->audio_.get();
    r->dispatcher_.subscribe("sound", [a](const HapticEvent& e) { a->play(e); });
  }
  return r;
}

Status RunEvents::pump(EventQueue& queue) {
  dispatcher_.pump(queue);
  return log_ ? log_->flush() : ok_status();
}

Status RunEvents::close(EventQueue& queue) {
  dispatcher_.pump(queue);
  return log_ ? log_->close() : ok_status();
}

}  // namespace ps
