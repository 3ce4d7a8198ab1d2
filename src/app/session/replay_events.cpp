#include "app/session/replay_events.h"

#include "audio/track.h"

namespace ps {

Result<std::unique_ptr<ReplayEvents>> ReplayEvents::open(const ReplayEventsDesc& desc) {
  std::unique_ptr<ReplayEvents> r(new ReplayEvents);
  r->desc_ = desc;
  if (!desc.log_path.empty()) {
    auto log = EventLog::open(desc.log_path);
    if (!log) return log.error();
    r->log_ = std::move(log.value());
    EventLog* l = r->log_.get();
    // Flushed per event (they are few): a replay that crashes leaves them in the .partial file.
    r->dispatcher_.subscribe("event log", [l](const HapticEvent& e) {
      l->append(e);
      (void)l->flush();  // a write error is kept and returned by close() in finish()
    });
  }
  if (!desc.audio_path.empty()) {
    std::vector<HapticEvent>* events = &r->for_track_;
    r->dispatcher_.subscribe("sound track", [events](const HapticEvent& e) { events->push_back(e); });
  }
  return r;
}

ReplayEvents::~ReplayEvents() {
  if (log_) log_->discard();  // no-op after close()
}

Status ReplayEvents::finish(OutputSet& out) {
  if (log_)
    if (Status s = log_->close(); !s) return s;
  if (desc_.audio_path.empty()) return ok_status();
  const int rate = desc_.synth.sample_rate_hz;
  const std::vector<float> track =
      audio::mix_track(for_track_, audio::track_length(desc_.duration_s, rate), desc_.synth);
  return out.stage(desc_.audio_path, [&](const std::string& file) { return audio::write_wav(file, track, rate); });
}

}  // namespace ps
