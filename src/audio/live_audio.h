// Live event sounds for `run`, through OpenAL (OpenAL Soft on Debian; why OpenAL: docs/sound.md).
// The render thread calls play(event): it only pushes the event into a lock-free single-producer
// queue (haptics/events.h) and wakes the audio thread, so it never waits on audio. The audio
// thread synthesises the clip (audio/synth.h) into a buffer and starts it on a free source of a
// small pool (the oldest one is cut when all are busy).
// Without an audio device (CI, Xvfb, a server) or with `mute`, open() still succeeds: the player
// is silent, play() does nothing, and warning() holds one line saying why.
// The output going away while running (a USB card unplugged, the sound server ended) is one
// notice, said by the audio thread when it next has a sound to start (OpenAL's ALC_CONNECTED,
// ALC_EXT_disconnect); from then on the events are taken and counted as not played, and the rest
// of the session runs. OpenAL Soft 1.19 cannot reopen a device, so the sound stays off until the
// next session (as the vibration's sound, vibration/live.h).
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "audio/synth.h"
#include "haptics/events.h"

namespace ps::audio {

struct LiveAudioDesc {
  bool mute = false;
  std::string device;  // OpenAL device name; empty: the default device
  SynthParams synth;
  std::size_t queue_capacity = 256;  // events waiting for the audio thread; more are dropped
  int voices = 16;                   // sounds playing at once
  // Where a notice goes (the output lost), called on the audio thread; empty: one line on stderr.
  std::function<void(const std::string&)> notice;
};

class LiveAudio {
 public:
  static std::unique_ptr<LiveAudio> open(const LiveAudioDesc& desc);
  ~LiveAudio();
  LiveAudio(const LiveAudio&) = delete;
  LiveAudio& operator=(const LiveAudio&) = delete;

  bool active() const { return impl_ != nullptr; }
  const std::string& warning() const { return warning_; }  // empty when active
  const std::string& device_name() const { return device_name_; }

  void play(const HapticEvent& e);  // render thread; never blocks
  // Starts what is queued, then stops the audio thread and closes the device (the destructor
  // does it too). play() after close() does nothing.
  void close();
  // The audio thread's counts (for tests and the summary).
  std::uint64_t started() const { return started_.load(std::memory_order_relaxed); }
  std::uint64_t dropped() const;
  // The output went away while running; unplayed(): the events taken after that.
  bool lost() const { return lost_.load(std::memory_order_acquire); }
  std::uint64_t unplayed() const { return unplayed_.load(std::memory_order_relaxed); }
  std::vector<std::string> notices() const;
  // "event sounds: 12 started on 'OpenAL Soft', 0 dropped", with "; the output went away, 3 not
  // played" after a loss; "event sounds: off" when inactive.
  std::string summary() const;

 private:
  struct Impl;
  LiveAudio() = default;
  std::unique_ptr<Impl> impl_;
  void say(const std::string& line);  // the audio thread
  std::function<void(const std::string&)> notice_;  // LiveAudioDesc::notice
  std::string warning_, device_name_;
  std::atomic<std::uint64_t> started_{0}, unplayed_{0};
  std::atomic<bool> lost_{false};
  mutable std::mutex notices_mutex_;  // guards notices_
  std::vector<std::string> notices_;
};

}  // namespace ps::audio
