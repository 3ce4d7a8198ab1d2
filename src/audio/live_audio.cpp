#include "audio/live_audio.h"

#include <cstdio>
#include <thread>
#include <vector>

#include <AL/al.h>
#include <AL/alc.h>
#include <AL/alext.h>

#include "audio/quiet_stderr.h"
#include "audio/track.h"

namespace ps::audio {

struct LiveAudio::Impl {
  explicit Impl(const LiveAudioDesc& d) : desc(d), queue(d.queue_capacity) {}
  LiveAudioDesc desc;
  ALCdevice* device = nullptr;
  ALCcontext* context = nullptr;
  bool reports_disconnect = false;       // ALC_EXT_disconnect: ALC_CONNECTED can be asked
  std::vector<ALuint> sources, buffers;  // one buffer per source
  std::size_t next_voice = 0;            // round robin when every source is busy
  EventQueue queue;                      // render thread -> audio thread
  std::atomic<std::uint32_t> wake{0};
  std::atomic<bool> stop{false};
  std::thread thread;

  void start_clip(const HapticEvent& e, std::atomic<std::uint64_t>& started) {
    const std::vector<std::int16_t> pcm = to_pcm16(event_sound(e, desc.synth));
    if (pcm.empty()) return;
    std::size_t v = sources.size();
    for (std::size_t i = 0; i < sources.size(); ++i) {
      ALint state = AL_STOPPED;
      alGetSourcei(sources[i], AL_SOURCE_STATE, &state);
      if (state != AL_PLAYING) {
        v = i;
        break;
      }
    }
    if (v == sources.size()) v = next_voice++ % sources.size();  // all busy: cut the oldest
    alSourceStop(sources[v]);
    alSourcei(sources[v], AL_BUFFER, 0);  // a buffer attached to a source cannot be refilled
    alBufferData(buffers[v], AL_FORMAT_MONO16, pcm.data(), static_cast<ALsizei>(pcm.size() * 2),
                 desc.synth.sample_rate_hz);
    alSourcei(sources[v], AL_BUFFER, static_cast<ALint>(buffers[v]));
    alSourcePlay(sources[v]);
    if (alGetError() == AL_NO_ERROR) started.fetch_add(1, std::memory_order_relaxed);
  }

  bool connected() const {
    if (!reports_disconnect) return true;
    ALCint c = 1;
    alcGetIntegerv(device, ALC_CONNECTED, 1, &c);
    return c != 0;
  }

  // Starts what is queued; once the output is gone, takes it and counts it as not played.
  void drain(LiveAudio& owner) {
    if (!owner.lost() && !connected()) {
      owner.lost_.store(true, std::memory_order_release);
      owner.say("sound: the audio output '" + owner.device_name_ +
                "' went away: event sounds stopped until the next session; the rest runs");
    }
    if (owner.lost()) {
      queue.drain([&](const HapticEvent&) { owner.unplayed_.fetch_add(1, std::memory_order_relaxed); });
      return;
    }
    queue.drain([&](const HapticEvent& e) { start_clip(e, owner.started_); });
  }

  void run(LiveAudio& owner) {
    alcMakeContextCurrent(context);
    for (;;) {
      const std::uint32_t seen = wake.load(std::memory_order_acquire);
      drain(owner);
      if (stop.load(std::memory_order_acquire)) {
        // What play() queued before close() is visible now (stop was stored after it): start it.
        drain(owner);
        break;
      }
      wake.wait(seen, std::memory_order_acquire);  // until play() or the destructor bumps it
    }
  }

  ~Impl() {
    if (thread.joinable()) {
      stop.store(true, std::memory_order_release);
      wake.fetch_add(1, std::memory_order_release);
      wake.notify_one();
      thread.join();
    }
    if (context != nullptr) {
      alcMakeContextCurrent(context);
      if (!sources.empty()) alDeleteSources(static_cast<ALsizei>(sources.size()), sources.data());
      if (!buffers.empty()) alDeleteBuffers(static_cast<ALsizei>(buffers.size()), buffers.data());
      alcMakeContextCurrent(nullptr);
      alcDestroyContext(context);
    }
    if (device != nullptr) alcCloseDevice(device);
  }
};

std::unique_ptr<LiveAudio> LiveAudio::open(const LiveAudioDesc& desc) {
  std::unique_ptr<LiveAudio> a(new LiveAudio);
  a->notice_ = desc.notice;
  if (desc.mute) {
    a->warning_ = "sound is off (--mute): the event log and everything else run as usual";
    return a;
  }
  auto impl = std::make_unique<Impl>(desc);
  {
    QuietStderr quiet;
    impl->device = alcOpenDevice(desc.device.empty() ? nullptr : desc.device.c_str());
    if (impl->device != nullptr) impl->context = alcCreateContext(impl->device, nullptr);
  }
  const std::string which = desc.device.empty() ? "the default audio device" : "audio device '" + desc.device + "'";
  if (impl->device == nullptr || impl->context == nullptr) {
    a->warning_ = "no audio device (OpenAL could not open " + which + "): sound is off, everything else runs";
    return a;
  }
  alcMakeContextCurrent(impl->context);
  const int voices = std::max(1, desc.voices);
  impl->sources.resize(voices);
  impl->buffers.resize(voices);
  alGenSources(voices, impl->sources.data());
  alGenBuffers(voices, impl->buffers.data());
  if (alGetError() != AL_NO_ERROR) {
    impl->sources.clear();
    impl->buffers.clear();
    a->warning_ = "OpenAL opened " + which + " but could not create sources: sound is off, everything else runs";
    return a;
  }
  const ALCchar* name = alcGetString(impl->device, ALC_DEVICE_SPECIFIER);
  a->device_name_ = name != nullptr ? name : "";
  impl->reports_disconnect = alcIsExtensionPresent(impl->device, "ALC_EXT_disconnect") == ALC_TRUE;
  alcMakeContextCurrent(nullptr);  // the audio thread makes it current
  Impl* raw = impl.get();
  LiveAudio* owner = a.get();  // outlives the thread: close() joins it first
  impl->thread = std::thread([raw, owner] { raw->run(*owner); });
  a->impl_ = std::move(impl);
  return a;
}

LiveAudio::~LiveAudio() { close(); }  // joins the audio thread before started_ goes

void LiveAudio::close() { impl_.reset(); }

void LiveAudio::play(const HapticEvent& e) {
  if (!impl_) return;
  impl_->queue.push(e);  // full: dropped and counted
  impl_->wake.fetch_add(1, std::memory_order_release);
  impl_->wake.notify_one();
}

std::uint64_t LiveAudio::dropped() const { return impl_ ? impl_->queue.dropped() : 0; }

void LiveAudio::say(const std::string& line) {
  {
    std::lock_guard<std::mutex> lock(notices_mutex_);
    notices_.push_back(line);
  }
  if (notice_) notice_(line);
  else std::fprintf(stderr, "%s\n", line.c_str());
}

std::vector<std::string> LiveAudio::notices() const {
  std::lock_guard<std::mutex> lock(notices_mutex_);
  return notices_;
}

std::string LiveAudio::summary() const {
  if (device_name_.empty()) return "event sounds: off";
  std::string out = "event sounds: " + std::to_string(started()) + " started on '" + device_name_ + "', " +
                    std::to_string(dropped()) + " dropped";
  if (lost()) out += "; the output went away, " + std::to_string(unplayed()) + " not played";
  return out;
}

}  // namespace ps::audio
