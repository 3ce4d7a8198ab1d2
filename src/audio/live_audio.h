// Live event sounds for `run`, through OpenAL (OpenAL Soft on Debian; why OpenAL: docs/sound.md).
// The render thread calls play(event): it only pushes the event into a lock-free single-producer
// queue (haptics/events.h) and wakes the audio thread, so it never waits on audio. The audio
// thread synthesises the clip (audio/synth.h) into a buffer and starts it on a free source of a
// small pool (the oldest one is cut when all are busy).
// Without an audio device (CI, Xvfb, a server) or with `mute`, open() still succeeds: the player
// is silent, play() does nothing, and warning() holds one line saying why.
#pragma once

#include <atomic>
#include <memory>
#include <string>

#include "audio/synth.h"
#include "haptics/events.h"

namespace ps::audio {

struct LiveAudioDesc {
  bool mute = false;
  std::string device;  // OpenAL device name; empty: the default device
  SynthParams synth;
  std::size_t queue_capacity = 256;  // events waiting for the audio thread; more are dropped
  int voices = 16;                   // sounds playing at once
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

 private:
  struct Impl;
  LiveAudio() = default;
  std::unique_ptr<Impl> impl_;
  std::string warning_, device_name_;
  std::atomic<std::uint64_t> started_{0};
};

}  // namespace ps::audio
