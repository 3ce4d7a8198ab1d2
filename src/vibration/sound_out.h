// The vibration's sound channel: a streaming OpenAL source on a device of its own (so a
// voice-coil actuator can be wired to it, apart from the event sounds of audio/live_audio.h),
// fed in chunks by one thread. The context is that thread's own (ALC_EXT_thread_local_context),
// so it never touches the process-wide current context the event sounds' thread uses.
// Latency is bounded, not left to grow: at most `max_queued` chunks wait in OpenAL; a chunk that
// finds the queue full is dropped (and counted). Playback starts (and restarts after running
// dry) once `prebuffer` chunks are queued.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include "core/result.h"

namespace ps::vibration {

struct SoundOutDesc {
  std::string device;        // OpenAL device name; empty: the default device
  int sample_rate_hz = 48000;
  int refresh_hz = 200;      // OpenAL Soft's mixer updates per second (ALC_REFRESH): a 5 ms period
  int chunk_samples = 240;   // one buffer: 5 ms at 48 kHz
  int max_queued = 4;        // chunks waiting in OpenAL at most (20 ms)
  int prebuffer = 2;         // chunks queued before playback (re)starts
};

class SoundOut {
 public:
  // Errors: no such device, no context, no thread-local context extension, no source.
  static Result<std::unique_ptr<SoundOut>> open(const SoundOutDesc& desc);
  ~SoundOut();
  SoundOut(const SoundOut&) = delete;
  SoundOut& operator=(const SoundOut&) = delete;

  // On the feeding thread, before queue() and mixed(): makes the context that thread's own.
  void bind_thread();
  // Queues one chunk (desc.chunk_samples samples, full scale 1). False: the queue was full and
  // the chunk is dropped.
  bool queue(std::span<const float> chunk);
  // Samples OpenAL has mixed out of the source since open (its playback position over every
  // queued chunk), and samples queued so far (dropped chunks not counted).
  std::uint64_t mixed();
  std::uint64_t queued() const { return queued_samples_; }
  // The device's buffering after OpenAL's mixer (AL_SOFT_source_latency), ms; -1 if unknown.
  double device_latency_ms();
  std::uint64_t dropped() const { return dropped_; }
  std::uint64_t underruns() const { return underruns_; }
  const std::string& device_name() const { return device_name_; }
  // False once OpenAL reports the device gone (ALC_EXT_disconnect: a USB card unplugged, the
  // sound server ended, a write to the device failed); it never comes back on this device
  // (OpenAL Soft 1.19 cannot reopen one). True where the extension is missing.
  bool connected() const;

 private:
  struct Impl;
  SoundOut() = default;
  void reclaim();  // unqueues the buffers OpenAL finished with
  std::unique_ptr<Impl> impl_;
  SoundOutDesc desc_;
  std::string device_name_;
  std::uint64_t queued_samples_ = 0, processed_samples_ = 0, dropped_ = 0, underruns_ = 0;
  bool started_ = false;
};

}  // namespace ps::vibration
