#include "haptics/session_driver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

namespace ps {

std::uint64_t FrameSchedule::tick_of_frame(int i) const {
  return static_cast<std::uint64_t>(std::floor(i / fps * rate_hz + 1e-9));
}

std::uint64_t FrameSchedule::ticks_in(double duration_s) const {
  return static_cast<std::uint64_t>(std::floor(std::max(0.0, duration_s) * rate_hz + 1e-9)) + 1;
}

int FrameSchedule::frames_in(double duration_s) const {
  return static_cast<int>(std::floor(std::max(0.0, duration_s) * fps + 1e-9)) + 1;
}

namespace {

// The driver's feed is drained after every tick: any room does (TickFeed's default).
constexpr std::size_t kDriverFeedTicks = 4096;

}  // namespace

RecordedLoop::RecordedLoop(Device& device, Clock& clock, const HapticLoopParams& params,
                           std::shared_ptr<const world::HapticScene> scene, const std::string& record_path,
                           std::size_t feed_ticks)
    : recording_(!record_path.empty()),
      recorder_(record_path),
      feed_(feed_ticks > 0 ? std::make_unique<TickFeed>(feed_ticks) : nullptr),
      loop_(device, clock, params, std::move(scene)) {
  if (recording_) loop_.set_recorder(&recorder_);
  if (feed_) loop_.add_tick_feed(feed_.get());
}

RecordedLoop::~RecordedLoop() { stop_flushing(); }

Status RecordedLoop::flush_due(double time_s) {
  if (flusher_.joinable()) {
    std::lock_guard<std::mutex> lock(flush_mutex_);
    return flush_error_.empty() ? ok_status() : make_error(flush_error_);
  }
  if (!recording_ || time_s - flushed_s_ < 1.0) return ok_status();
  flushed_s_ = time_s;
  return recorder_.flush();
}

void RecordedLoop::start_flushing() {
  if (!recording_ || flusher_.joinable()) return;
  flush_stop_ = false;
  flusher_ = std::thread([this] { flush_every_second(); });
}

void RecordedLoop::flush_every_second() {
  std::unique_lock<std::mutex> lock(flush_mutex_);
  while (!flush_wake_.wait_for(lock, std::chrono::seconds(1), [this] { return flush_stop_; })) {
    lock.unlock();
    const Status s = recorder_.flush();
    lock.lock();
    if (!s) {
      flush_error_ = s.error().message;
      return;
    }
  }
}

void RecordedLoop::stop_flushing() {
  if (!flusher_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(flush_mutex_);
    flush_stop_ = true;
  }
  flush_wake_.notify_all();
  flusher_.join();
}

Status RecordedLoop::finish() {
  if (!recording_) return ok_status();
  stop_flushing();
  if (!flush_error_.empty()) return make_error(flush_error_);
  return recorder_.close();
}

SessionDriver::SessionDriver(Device& device, const HapticLoopParams& params, const world::HapticScene* scene,
                             const std::string& record_path, FrameSchedule schedule, DriverHooks hooks)
    : schedule_(schedule),
      hooks_(std::move(hooks)),
      // Not owned (the aliasing constructor with no owner): the driver ticks on its caller's
      // thread, which keeps the scene for the whole run.
      recorded_(device, clock_, params, std::shared_ptr<const world::HapticScene>(std::shared_ptr<void>(), scene),
                record_path, hooks_.on_tick ? kDriverFeedTicks : 0) {}

Result<DriveResult> SessionDriver::run(std::uint64_t ticks, int max_frames) {
  DriveResult out;
  if (!hooks_.on_frame || !(schedule_.fps > 0.0)) max_frames = 0;
  for (std::uint64_t k = 0; k < ticks; ++k) {
    // Between ticks: every tick before has been handed on, drawn and recorded.
    if (hooks_.stop && hooks_.stop()) {
      out.stopped = true;
      break;
    }
    if (Status s = tick(k); !s) return s.error();
    out.ticks = k + 1;
    if (Status s = frames_due(k, max_frames, out.frames); !s) return s.error();
    // Once per second of session time: (k + 1) / rate is exact at each whole second.
    if (Status s = recorded_.flush_due(static_cast<double>(k + 1) / schedule_.rate_hz); !s) return s.error();
  }
  return out;
}

Status SessionDriver::tick(std::uint64_t k) {
  HapticLoop& loop = recorded_.loop();
  loop.run_ticks(1);
  if (TickFeed* feed = recorded_.feed()) feed->drain(hooks_.on_tick);
  if (hooks_.after_tick) return hooks_.after_tick(k, loop.state().read());
  return ok_status();
}

// Every frame due after tick k: its events drained first, then on_frame.
Status SessionDriver::frames_due(std::uint64_t k, int max_frames, int& frame) {
  while (frame < max_frames && schedule_.tick_of_frame(frame) <= k) {
    if (hooks_.on_event) recorded_.loop().events().drain(hooks_.on_event);
    if (Status s = hooks_.on_frame(frame); !s) return s;
    ++frame;
  }
  return ok_status();
}

}  // namespace ps
