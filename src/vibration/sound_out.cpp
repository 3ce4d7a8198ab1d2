#include "vibration/sound_out.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <AL/al.h>
#include <AL/alc.h>
#include <AL/alext.h>

#include "audio/quiet_stderr.h"

namespace ps::vibration {

struct SoundOut::Impl {
  ALCdevice* device = nullptr;
  ALCcontext* context = nullptr;
  PFNALCSETTHREADCONTEXTPROC set_thread_context = nullptr;
  LPALGETSOURCEI64VSOFT get_source_i64 = nullptr;  // AL_SOFT_source_latency, if present
  bool reports_disconnect = false;                 // ALC_EXT_disconnect
  ALuint source = 0;
  std::vector<ALuint> buffers, free;
  std::vector<std::int16_t> pcm;  // one chunk, converted
  ~Impl() {
    if (context != nullptr && set_thread_context != nullptr) {
      set_thread_context(context);
      if (source != 0) {
        alSourceStop(source);
        alSourcei(source, AL_BUFFER, 0);
        alDeleteSources(1, &source);
      }
      if (!buffers.empty()) alDeleteBuffers(static_cast<ALsizei>(buffers.size()), buffers.data());
      set_thread_context(nullptr);
      alcDestroyContext(context);
    }
    if (device != nullptr) alcCloseDevice(device);
  }
};

Result<std::unique_ptr<SoundOut>> SoundOut::open(const SoundOutDesc& desc) {
  std::unique_ptr<SoundOut> out(new SoundOut);
  out->desc_ = desc;
  out->impl_ = std::make_unique<Impl>();
  Impl& im = *out->impl_;
  const std::string which = desc.device.empty() ? "the default audio device" : "audio device '" + desc.device + "'";
  {
    audio::QuietStderr quiet;  // libasound's own lines when there is no card
    im.device = alcOpenDevice(desc.device.empty() ? nullptr : desc.device.c_str());
    // Our rate and a short mixer period: OpenAL Soft's default period (1024 frames, ~21 ms)
    // alone would spend the whole latency budget.
    const ALCint attrs[] = {ALC_FREQUENCY, desc.sample_rate_hz, ALC_REFRESH, desc.refresh_hz, 0};
    if (im.device != nullptr) im.context = alcCreateContext(im.device, attrs);
  }
  if (im.device == nullptr || im.context == nullptr) return make_error("OpenAL could not open " + which);
  if (alcIsExtensionPresent(im.device, "ALC_EXT_thread_local_context") == ALC_FALSE)
    return make_error("OpenAL has no ALC_EXT_thread_local_context on " + which);
  im.set_thread_context =
      reinterpret_cast<PFNALCSETTHREADCONTEXTPROC>(alcGetProcAddress(im.device, "alcSetThreadContext"));
  if (im.set_thread_context == nullptr) return make_error("OpenAL: alcSetThreadContext missing");
  im.reports_disconnect = alcIsExtensionPresent(im.device, "ALC_EXT_disconnect") == ALC_TRUE;
  im.set_thread_context(im.context);
  alGetError();
  if (alIsExtensionPresent("AL_SOFT_source_latency") == AL_TRUE)
    im.get_source_i64 = reinterpret_cast<LPALGETSOURCEI64VSOFT>(alGetProcAddress("alGetSourcei64vSOFT"));
  alGenSources(1, &im.source);
  im.buffers.resize(static_cast<std::size_t>(std::max(1, desc.max_queued) + 2));
  alGenBuffers(static_cast<ALsizei>(im.buffers.size()), im.buffers.data());
  const bool ok = alGetError() == AL_NO_ERROR;
  im.set_thread_context(nullptr);
  if (!ok) return make_error("OpenAL opened " + which + " but could not create a source");
  im.free = im.buffers;
  im.pcm.resize(static_cast<std::size_t>(desc.chunk_samples));
  const ALCchar* name = alcGetString(im.device, ALC_ALL_DEVICES_SPECIFIER);
  if (name == nullptr) name = alcGetString(im.device, ALC_DEVICE_SPECIFIER);
  out->device_name_ = name != nullptr ? name : "";
  return out;
}

SoundOut::~SoundOut() = default;

void SoundOut::bind_thread() { impl_->set_thread_context(impl_->context); }

void SoundOut::reclaim() {
  ALint processed = 0;
  alGetSourcei(impl_->source, AL_BUFFERS_PROCESSED, &processed);
  while (processed-- > 0) {
    ALuint b = 0;
    alSourceUnqueueBuffers(impl_->source, 1, &b);
    impl_->free.push_back(b);
    processed_samples_ += static_cast<std::uint64_t>(desc_.chunk_samples);
  }
}

bool SoundOut::queue(std::span<const float> chunk) {
  reclaim();
  ALint waiting = 0;
  alGetSourcei(impl_->source, AL_BUFFERS_QUEUED, &waiting);
  if (waiting >= desc_.max_queued || impl_->free.empty()) {
    ++dropped_;
    return false;
  }
  const std::size_t n = std::min(chunk.size(), impl_->pcm.size());
  for (std::size_t i = 0; i < n; ++i)  // as the WAV: round(clamp(x, -1, 1) * 32767)
    impl_->pcm[i] = static_cast<std::int16_t>(std::lround(std::clamp(static_cast<double>(chunk[i]), -1.0, 1.0) * 32767.0));
  const ALuint b = impl_->free.back();
  impl_->free.pop_back();
  alBufferData(b, AL_FORMAT_MONO16, impl_->pcm.data(), static_cast<ALsizei>(n * sizeof(std::int16_t)),
               desc_.sample_rate_hz);
  alSourceQueueBuffers(impl_->source, 1, &b);
  queued_samples_ += n;
  ALint state = 0;
  alGetSourcei(impl_->source, AL_SOURCE_STATE, &state);
  if (state != AL_PLAYING && waiting + 1 >= desc_.prebuffer) {
    if (started_) ++underruns_;  // it had played everything it had and stopped
    alSourcePlay(impl_->source);
    started_ = true;
  }
  return true;
}

std::uint64_t SoundOut::mixed() {
  reclaim();
  ALint offset = 0;
  alGetSourcei(impl_->source, AL_SAMPLE_OFFSET, &offset);
  return processed_samples_ + static_cast<std::uint64_t>(std::max(0, offset));
}

bool SoundOut::connected() const {
  if (!impl_->reports_disconnect) return true;
  ALCint connected = 1;
  alcGetIntegerv(impl_->device, ALC_CONNECTED, 1, &connected);
  return connected != 0;
}

double SoundOut::device_latency_ms() {
  if (impl_->get_source_i64 == nullptr) return -1.0;
  ALint64SOFT v[2] = {0, 0};  // sample offset (32.32 fixed point), latency in ns
  impl_->get_source_i64(impl_->source, AL_SAMPLE_OFFSET_LATENCY_SOFT, v);
  return static_cast<double>(v[1]) * 1e-6;
}

}  // namespace ps::vibration
