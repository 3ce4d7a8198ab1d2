#include "vibration/live.h"

#include <pthread.h>

#include <chrono>
#include <cstdio>

namespace ps::vibration {

namespace {

constexpr const char* kChoices = "none, sound, sound:DEVICE, gamepad, both, both:DEVICE";

// The outputs are looked at every 100 wakes (0.1 s): a lost output is noticed within that, and
// looking costs a query to OpenAL and SDL's joystick update. A gamepad is looked for every 0.5 s.
constexpr std::uint64_t kCheckWakes = 100, kReattachWakes = 500;

std::int64_t steady_ns() { return std::chrono::steady_clock::now().time_since_epoch().count(); }

}  // namespace

Result<OutputChoice> parse_output_choice(const std::string& value) {
  OutputChoice c;
  const std::size_t colon = value.find(':');
  const std::string kind = value.substr(0, colon);
  if (colon != std::string::npos) {
    c.sound_device = value.substr(colon + 1);
    if (kind != "sound" && kind != "both")
      return make_error("--vibration-out: only sound and both take a device ('" + value + "'; choices: " + kChoices + ")");
    if (c.sound_device.empty()) return make_error("--vibration-out: empty device name in '" + value + "'");
  }
  if (kind == "sound" || kind == "both") c.sound = true;
  if (kind == "gamepad" || kind == "both") c.gamepad = true;
  if (kind != "none" && !c.sound && !c.gamepad)
    return make_error("--vibration-out: unknown output '" + value + "' (choices: " + kChoices + ")");
  return c;
}

LiveVibration::LiveVibration(const LiveDesc& desc, const Scene& scene)
    : desc_(desc), feed_(desc.feed_capacity), synth_(std::make_shared<const SignalModel>(scene, desc.signal)) {}

std::unique_ptr<LiveVibration> LiveVibration::open(const LiveDesc& desc, const Scene& scene) {
  std::unique_ptr<LiveVibration> v(new LiveVibration(desc, scene));
  if (desc.out.sound) {
    SoundOutDesc s = desc.sound;
    s.device = desc.out.sound_device;
    s.sample_rate_hz = desc.signal.sample_rate_hz;
    auto out = SoundOut::open(s);
    if (out) v->sound_ = std::move(out.value());
    else v->warnings_.push_back("no vibration sound (" + out.error().message + "): the rest runs");
  }
  if (desc.out.gamepad) {
    RumbleDesc r = desc.rumble;
    r.sample_rate_hz = desc.signal.sample_rate_hz;
    auto out = RumbleOut::open(r);
    if (out) v->rumble_ = std::move(out.value());
    else v->warnings_.push_back("no gamepad rumble (" + out.error().message + "): the rest runs");
  }
  return v;
}

LiveVibration::~LiveVibration() { close(); }

void LiveVibration::set_scene(const Scene& scene) {
  if (!active()) return;  // nothing plays it
  auto model = std::make_shared<const SignalModel>(scene, desc_.signal);  // built here, not on our thread
  std::lock_guard<std::mutex> lock(scene_mutex_);
  pending_scene_ = std::move(model);
}

void LiveVibration::start() {
  if (!active() || thread_.joinable()) return;
  stop_.store(false);
  thread_ = std::thread([this] {
    pthread_setname_np(pthread_self(), "ps-vibration");
    run();
  });
}

void LiveVibration::close() {
  stop_.store(true);
  if (thread_.joinable()) thread_.join();
}

// Splits the pending samples into chunks and hands each to the outputs; for the sound channel
// remembers where each tick's sample (the one at its time) sits in the queued stream.
void LiveVibration::emit_chunks() {
  const std::size_t n = static_cast<std::size_t>(desc_.sound.chunk_samples);
  std::size_t used = 0;
  while (pending_.size() - used >= n) {
    const std::span<const float> chunk(pending_.data() + used, n);
    const std::uint64_t first = pending_start_ + used, end = first + n;
    const std::uint64_t position = sound_ ? sound_->queued() : 0;
    const bool queued = sound_ && !sound_gone_ && sound_->queue(chunk);
    if (rumble_ && !rumble_gone_) rumble_->write(chunk);
    std::size_t keep = 0;
    for (const TickMark& t : ticks_) {
      if (t.sample >= end) ticks_[keep++] = t;
      else if (queued) waiting_.push_back({position + (t.sample - first), t.clock_ns});
    }
    ticks_.resize(keep);
    used += n;
  }
  pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(used));
  pending_start_ += used;
}

void LiveVibration::poll_latency() {
  if (!sound_ || sound_gone_ || waiting_.empty()) return;
  const std::uint64_t mixed = sound_->mixed();
  const std::int64_t now = steady_ns();
  const double device_ms = sound_->device_latency_ms();
  if (device_ms >= 0.0) device_latency_ms_.push_back(device_ms);
  std::size_t keep = 0;
  for (const Waiting& w : waiting_) {
    if (w.position < mixed) latency_ms_.push_back(static_cast<double>(now - w.clock_ns) * 1e-6);
    else waiting_[keep++] = w;
  }
  waiting_.resize(keep);
}

void LiveVibration::say(const std::string& line) {
  {
    std::lock_guard<std::mutex> lock(notices_mutex_);
    notices_.push_back(line);
  }
  if (desc_.notice) desc_.notice(line);
  else std::fprintf(stderr, "%s\n", line.c_str());
}

std::vector<std::string> LiveVibration::notices() const {
  std::lock_guard<std::mutex> lock(notices_mutex_);
  return notices_;
}

void LiveVibration::check_outputs() {
  if (sound_ && !sound_gone_ && !sound_->connected()) {
    sound_gone_ = true;
    waiting_.clear();  // their samples will never leave
    say("vibration: the audio output '" + sound_->device_name() +
        "' went away: vibration sound stopped until the next session; the rest runs");
  }
  if (!rumble_) return;
  if (!rumble_gone_ && !rumble_->attached()) {
    rumble_gone_ = true;
    say("vibration: the gamepad '" + rumble_->name() +
        "' went away: rumble stopped until a gamepad with rumble is connected; the rest runs");
  } else if (rumble_gone_ && wakes_ % kReattachWakes == 0 && rumble_->reattach()) {
    rumble_gone_ = false;
    say("vibration: rumble back on '" + rumble_->name() + "'");
  }
}

void LiveVibration::run() {
  if (sound_) sound_->bind_thread();
  auto next = std::chrono::steady_clock::now();
  while (!stop_.load(std::memory_order_relaxed)) {
    next += std::chrono::milliseconds(1);
    std::this_thread::sleep_until(next);
    if (std::chrono::steady_clock::now() - next > std::chrono::milliseconds(50))
      next = std::chrono::steady_clock::now();  // after a stall: no burst of catch-up wakes
    {
      std::lock_guard<std::mutex> lock(scene_mutex_);
      if (pending_scene_) synth_.set_model(std::move(pending_scene_));
    }
    feed_.drain([this](const TickSample& s) {
      const std::size_t before = pending_.size();
      synth_.add_tick(s, pending_);
      // Only a tick with a sample of its own is measured: after a stall the loop runs the missed
      // ticks back to back at one clock time, and they share the sample of the first.
      if (pending_.size() > before) ticks_.push_back({pending_start_ + pending_.size() - 1, s.clock_ns});
      ++ticks_seen_;
    });
    emit_chunks();
    poll_latency();
    if (++wakes_ % kCheckWakes == 0) check_outputs();
  }
}

std::string LiveVibration::summary() const {
  std::string out = "vibration:";
  if (sound_) out += " sound on '" + sound_->device_name() + "'" + (sound_gone_ ? " (lost)" : "");
  if (rumble_) out += std::string(sound_ ? "," : "") + " rumble on '" + rumble_->name() + "'" + (rumble_gone_ ? " (lost)" : "");
  if (!active()) return out + " off";
  char buf[256];
  const Percentiles l = latency_ms();
  std::snprintf(buf, sizeof buf, "; %llu ticks", static_cast<unsigned long long>(ticks_seen()));
  out += buf;
  if (sound_) {
    std::snprintf(buf, sizeof buf,
                  "; latency tick -> sample out of OpenAL ms p50 %.1f p99 %.1f max %.1f (%zu ticks measured); "
                  "then the device's buffer (OpenAL's figure) ms p50 %.1f; chunks dropped %llu, underruns %llu",
                  l.p50, l.p99, l.max, l.count, device_latency_ms().p50,
                  static_cast<unsigned long long>(sound_->dropped()),
                  static_cast<unsigned long long>(sound_->underruns()));
    out += buf;
  }
  std::snprintf(buf, sizeof buf, "; feed drops %llu", static_cast<unsigned long long>(feed_.dropped()));
  return out + buf;
}

}  // namespace ps::vibration
