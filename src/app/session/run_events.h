// What `run` does with the haptic events: one EventDispatcher (app/session/event_dispatch.h) drained
// once per frame on the render thread, with the event log (--events) and the live sound
// (audio/live_audio.h) subscribed. Other consumers subscribe to dispatcher().
#pragma once

#include <memory>
#include <string>

#include "app/session/event_dispatch.h"
#include "app/session/event_log.h"
#include "audio/live_audio.h"
#include "core/result.h"

namespace ps {

struct RunEventsDesc {
  std::string log_path;           // empty: no event log
  audio::LiveAudioDesc audio;     // audio.mute: no sound (one warning line)
};

class RunEvents {
 public:
  // Fails only for the log (a bad path); a missing audio device is a warning(), not an error.
  static Result<std::unique_ptr<RunEvents>> open(const RunEventsDesc& desc);

  EventDispatcher& dispatcher() { return dispatcher_; }
  const std::string& warning() const { return audio_->warning(); }  // empty: sound is on
  const audio::LiveAudio& audio() const { return *audio_; }

  Status pump(EventQueue& queue);   // each frame: drain, fan out, flush the log
  Status close(EventQueue& queue);  // after the haptic thread stopped: the rest, then the log

 private:
  RunEvents() = default;
  EventDispatcher dispatcher_;
  std::unique_ptr<EventLog> log_;
  std::unique_ptr<audio::LiveAudio> audio_;
};

}  // namespace ps
