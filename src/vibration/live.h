// The live vibration of `run` and `maze`: the haptic thread pushes one TickSample per tick into
// feed() (HapticLoop::add_tick_feed, haptics/tick_feed.h: no lock, no allocation, no GL); a
// thread of ours wakes every millisecond, drains it, turns the ticks into samples
// (vibration/signal.h) and hands 5 ms chunks to the outputs: a sound channel of its own
// (vibration/sound_out.h) and a gamepad's rumble (vibration/rumble.h). Never waits for a frame.
// An output that cannot open is one warning line; the rest runs. An output that goes away while
// running (the audio device unplugged or its server ended, the gamepad unplugged) is one notice
// line too: that output stops, the rest runs; a gamepad plugged back in (or another with rumble)
// rumbles again, with a notice (OpenAL Soft 1.19 cannot reopen a lost device, so the sound stays
// off until the next session).
// Latency, measured (not assumed): for every tick of each queued chunk, its loop clock time
// against the moment OpenAL's playback position passes that tick's sample (polled every wake);
// beside it, the device's own buffering after the mixer as OpenAL reports it.
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "haptics/loop_stats.h"
#include "haptics/tick_feed.h"
#include "vibration/rumble.h"
#include "vibration/signal.h"
#include "vibration/sound_out.h"

namespace ps::vibration {

// --vibration-out: none | sound | sound:DEVICE | gamepad | both | both:DEVICE
struct OutputChoice {
  bool sound = false, gamepad = false;
  std::string sound_device;  // empty: the default device
};
// Errors name the value and list the choices.
Result<OutputChoice> parse_output_choice(const std::string& value);

struct LiveDesc {
  OutputChoice out;
  SignalParams signal;
  SoundOutDesc sound;
  RumbleDesc rumble;
  std::size_t feed_capacity = 1024;  // ticks (1 s): the thread drains it every millisecond
  // Where an output's loss or return is said, on the vibration thread; empty: standard error.
  std::function<void(const std::string&)> notice;
};

class LiveVibration {
 public:
  // Opens the chosen outputs (each that fails: one warning line). Does not start the thread.
  static std::unique_ptr<LiveVibration> open(const LiveDesc& desc, const Scene& scene);
  ~LiveVibration();
  LiveVibration(const LiveVibration&) = delete;
  LiveVibration& operator=(const LiveVibration&) = delete;

  bool active() const { return sound_ != nullptr || rumble_ != nullptr; }
  const std::vector<std::string>& warnings() const { return warnings_; }
  TickFeed& feed() { return feed_; }  // HapticLoop::add_tick_feed, before the loop starts
  // A new scene (reload, a button's switch): any thread; the vibration thread adopts it.
  void set_scene(const Scene& scene);
  void start();
  void close();  // joins the thread; idempotent
  // After close(): ms from a tick (loop clock) to its sample leaving OpenAL's mixer.
  Percentiles latency_ms() const { return percentiles(latency_ms_); }
  // After close(): the device's own buffering after that, as OpenAL reports it (AL_SOFT_source_latency;
  // empty if the extension is missing).
  Percentiles device_latency_ms() const { return percentiles(device_latency_ms_); }
  std::string summary() const;  // one line: outputs, latency, drops
  // What was said of outputs lost or back so far (any thread).
  std::vector<std::string> notices() const;
  std::uint64_t ticks_seen() const { return ticks_seen_.load(std::memory_order_relaxed); }

 private:
  LiveVibration(const LiveDesc& desc, const Scene& scene);
  void run();
  void emit_chunks();
  void poll_latency();
  void check_outputs();  // every kCheckWakes: an output gone or back
  void say(const std::string& line);
  LiveDesc desc_;
  TickFeed feed_;
  SignalSynth synth_;
  std::unique_ptr<SoundOut> sound_;
  std::unique_ptr<RumbleOut> rumble_;
  std::vector<std::string> warnings_;
  std::mutex scene_mutex_;  // guards pending_scene_
  std::shared_ptr<const SignalModel> pending_scene_;
  std::vector<float> pending_;  // samples not yet in a chunk
  std::uint64_t pending_start_ = 0;  // sample index of pending_[0]
  struct TickMark {
    std::uint64_t sample = 0;  // the tick's sample (signal index)
    std::int64_t clock_ns = 0;
  };
  std::vector<TickMark> ticks_;  // ticks whose samples are still pending
  struct Waiting {
    std::uint64_t position = 0;  // the tick's sample in the sound channel's queued stream
    std::int64_t clock_ns = 0;
  };
  std::vector<Waiting> waiting_;  // queued ticks whose sample has not left yet
  std::vector<double> latency_ms_, device_latency_ms_;
  std::atomic<std::uint64_t> ticks_seen_{0};
  std::uint64_t wakes_ = 0;
  bool sound_gone_ = false, rumble_gone_ = false;  // the vibration thread's own
  mutable std::mutex notices_mutex_;  // guards notices_
  std::vector<std::string> notices_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace ps::vibration
