// What `replay` does with the haptic events: the same EventDispatcher as `run`, with the event
// log and (--audio) the sound track subscribed. The track is mixed when the replay ends
// (audio/track.h) and staged in the command's OutputSet, so it appears with the frames or not
// at all; the log streams to "<FILE>.partial" like a --record log (app/session/event_log.h).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "app/session/event_dispatch.h"
#include "app/session/event_log.h"
#include "audio/synth.h"
#include "core/output_set.h"

namespace ps {

struct ReplayEventsDesc {
  std::string log_path;    // empty: no log
  std::string audio_path;  // empty: no track
  double duration_s = 0.0; // the session's length: the track covers [0, duration_s]
  audio::SynthParams synth;
};

class ReplayEvents {
 public:
  static Result<std::unique_ptr<ReplayEvents>> open(const ReplayEventsDesc& desc);
  ~ReplayEvents();  // without finish(): the log's .partial file is removed (the replay failed)

  EventDispatcher& dispatcher() { return dispatcher_; }
  // After the session: closes the log and stages the WAV in `out` (published with the frames).
  Status finish(OutputSet& out);
  std::size_t count() const { return dispatcher_.dispatched(); }

 private:
  ReplayEvents() = default;
  ReplayEventsDesc desc_;
  EventDispatcher dispatcher_;
  std::unique_ptr<EventLog> log_;
  std::vector<HapticEvent> for_track_;
};

}  // namespace ps
