#include "haptics/haptic_loop.h"

#include "devices/sample_log.h"
#include "haptics/effects/scene_effects.h"
#include "haptics/proxy_model.h"
#include "haptics/tick_feed.h"
#include "haptics/workspace.h"

#include <sched.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace ps {

// The tick's stages after the filter. The proxy model is chosen once per scene: the plane until
// a haptic scene is given, then the god-object in it.
struct HapticLoop::Stages {
  Stages(const Snapshot<SurfaceModel>& surface, const Snapshot<LiveCharges>& live_charges, double coupling_n_per_mm)
      : plane(surface), effects(live_charges, coupling_n_per_mm) {}
  // A scene adopted (its first, or one switched to): every stage starts afresh with it.
  void use_scene(const world::HapticScene& scene, bool after_switch) {
    god.emplace(scene);  // GodObject holds no heap memory (the effects' restart frees and allocates
                         // their small vectors here, on the haptic thread: glibc allows it)
    proxy = &*god;
    effects.restart(scene, after_switch);
    workspace.restart(&scene);
  }
  const world::GodObject* god_object() const { return god ? &god->god() : nullptr; }

  Workspace workspace;
  PlaneProxy plane;
  std::optional<GodObjectProxy> god;
  ProxyModel* proxy = &plane;
  SceneEffects effects;
  TickSample feed;  // this tick's record, filled as the tick goes (impact, click)
};

HapticLoop::HapticLoop(Device& device, Clock& clock, const HapticLoopParams& params,
                       const world::HapticScene* scene)
    : device_(device), clock_(clock), params_(params),
      period_(static_cast<std::int64_t>(std::llround(1e9 / params.rate_hz))),
      schedule_(period_, params.schedule),
      sanitizer_(params.sanitizer), kalman_(params.kalman), periods_us_(params.keep_periods),
      // A HUD window is 1 s of ticks (missed ticks are skipped, never run back to back); room
      // for 2 s all the same (beyond that the HUD's p99 skips samples).
      window_jitter_us_(2 * static_cast<std::size_t>(std::ceil(params.rate_hz)) + 16) {
  stages_ = std::make_unique<Stages>(surface_, live_charges_, params.forces.coupling_n_per_mm);
  if (scene != nullptr) stages_->use_scene(*scene, false);
  clock_.set_wake_spin(std::chrono::microseconds(std::max<std::int64_t>(params.wake_spin_us, 0)));
}

HapticLoop::HapticLoop(Device& device, Clock& clock, const HapticLoopParams& params,
                       std::shared_ptr<const world::HapticScene> scene)
    : HapticLoop(device, clock, params, scene.get()) {
  scene_owned_ = std::move(scene);  // retired at the switch that replaces it, as any adopted scene
}

HapticLoop::~HapticLoop() { stop(); }

void HapticLoop::stop() {
  stop_.store(true);
  if (thread_.joinable()) thread_.join();
}

void HapticLoop::run_ticks(std::uint64_t n) {
  for (std::uint64_t i = 0; i < n; ++i) scheduled_tick();
}

void HapticLoop::scheduled_tick() {
  if (!started_) {
    start_ = last_tick_ = window_start_ = clock_.now();
    schedule_.start(start_);
    started_ = true;
  } else {
    clock_.sleep_until(schedule_.deadline());
    note_wake(schedule_.woke(clock_.now()), clock_.now());
  }
  tick(clock_.now());
}

void HapticLoop::note_wake(const TickSchedule::Wake& w, Clock::Ns now) {
  local_.skipped_ticks += w.skipped;
  if (!w.stall) return;
  ++local_.stalls;
  local_.last_stall_ms = static_cast<double>(w.late.count()) * 1e-6;
  HapticEvent e = make_event(EventKind::tick_stall, local_.tick, session_time_s(now));
  e.index = static_cast<int>(std::min<std::uint64_t>(w.skipped, 1u << 30));
  e.value = local_.last_stall_ms;
  events_.push(e);
}

void HapticLoop::update_rate(Clock::Ns now) {
  if (local_.tick > 0) {
    const double period_us = static_cast<double>((now - last_tick_).count()) * 1e-3;
    periods_us_.push(period_us);  // dropped once keep_periods are logged
    window_jitter_us_.push(std::abs(period_us - static_cast<double>(period_.count()) * 1e-3));
    ++window_ticks_;
  }
  last_tick_ = now;
  const double window_s = static_cast<double>((now - window_start_).count()) * 1e-9;
  if (window_s >= 1.0) {  // HUD numbers, refreshed once per second
    local_.rate_hz = static_cast<double>(window_ticks_) / window_s;
    local_.jitter_p99_us = percentiles_in_place(window_jitter_us_.mutable_values()).p99;
    window_jitter_us_.clear();
    window_ticks_ = 0;
    window_start_ = now;
  }
}

std::uint64_t HapticLoop::replace_scene(std::shared_ptr<const world::HapticScene> scene, std::string_view label,
                                        std::optional<glm::dvec3> place_hand_mm) {
  std::shared_ptr<const world::HapticScene> drop;
  std::lock_guard<std::mutex> lock(swap_mutex_);
  drop = std::move(retired_);  // released here, on the caller's thread (after the lock: declared first)
  pending_ = std::move(scene);
  pending_label_.assign(label);
  pending_place_ = place_hand_mm;
  pending_place_normal_.reset();
  swap_pending_.store(true, std::memory_order_release);
  return ++scenes_requested_;
}

void HapticLoop::place_hand(const glm::dvec3& hand_mm, const glm::dvec3& normal, const glm::dvec3& surface_normal) {
  std::lock_guard<std::mutex> lock(swap_mutex_);
  pending_place_ = hand_mm;
  pending_place_normal_ = normal;
  pending_place_surface_ = surface_normal;
  swap_pending_.store(true, std::memory_order_release);
}

void HapticLoop::request_view_home(std::optional<glm::dvec3> place_hand_mm) {
  if (!place_hand_mm) {
    home_pending_.store(true, std::memory_order_release);
    return;
  }
  std::lock_guard<std::mutex> lock(swap_mutex_);
  pending_place_ = place_hand_mm;
  pending_place_normal_.reset();  // a restart at rest, as after a scene switch
  pending_home_ = true;
  swap_pending_.store(true, std::memory_order_release);
}

// The hand starts over again where it is put: at rest (a filter pulled from the old position
// would carry the hand through what lies between), and the proxy with it.
void HapticLoop::place(const glm::dvec3& hand_mm, const std::optional<glm::dvec3>& normal) {
  if (normal && kalman_.initialized()) {
    glm::dvec3 v = kalman_.velocity();
    v -= glm::dot(v, *normal) * *normal;
    const glm::dvec3& s = pending_place_surface_;
    v -= std::min(0.0, glm::dot(v, s)) * s;  // none of it into the surface under the hand
    kalman_.place(hand_mm, v);
    sanitizer_.restart();  // else it would clamp the placed sample into a 5 m/s ramp the filter takes for speed
  } else {
    restart_filter_now();
  }
  stages_->proxy->place(hand_mm);
  local_.proxy_mm = hand_mm;
}

// The filter starts afresh from the next sample, at rest there.
void HapticLoop::restart_filter_now() {
  kalman_ = Kalman3(params_.kalman);
  have_fed_ = false;
  sanitizer_.restart();
}

const world::HapticScene* HapticLoop::scene() const {
  const world::GodObject* god = stages_->god_object();
  return god != nullptr ? &god->scene() : nullptr;
}

void HapticLoop::adopt_pending_scene(Clock::Ns now) {
  // try_lock: the caller holds the mutex only to swap two pointers; if it is in there now, the
  // next tick adopts the scene instead of this one waiting.
  std::unique_lock<std::mutex> lock(swap_mutex_, std::try_to_lock);
  if (!lock.owns_lock()) return;
  swap_pending_.store(false, std::memory_order_relaxed);
  if (std::exchange(pending_home_, false)) stages_->workspace.home();
  if (!pending_) {  // a placement alone (place_hand, request_view_home)
    if (pending_place_) place(*pending_place_, pending_place_normal_);
    pending_place_.reset();
    pending_place_normal_.reset();
    return;
  }
  const world::GodObject* old = stages_->god_object();
  const bool had_proxy = old != nullptr && old->initialized();
  glm::dvec3 proxy = local_.proxy_mm;
  stages_->use_scene(*pending_, true);  // nothing fires until the probe has left a button
  if (pending_place_) {
    proxy = *pending_place_;
    place(proxy);
    pending_place_.reset();
    pending_place_normal_.reset();
  } else if (had_proxy) {
    stages_->proxy->place(proxy);
  }
  local_.flags = 0;  // flags are the scene's: a new scene starts with all of them off
  local_.scene_serial = scenes_requested_;  // published at this tick's end, with the probe placed
  retired_ = std::move(scene_owned_);
  scene_owned_ = std::move(pending_);
  HapticEvent e = make_event(EventKind::scene_switched, local_.tick, session_time_s(now));
  e.position_mm = proxy;
  e.set_label(pending_label_);
  events_.push(e);
}

// The tick's record for the vibration signal: the contact point on the surface (proxy centre
// minus the probe radius along the normal), the normal and the force along it.
void HapticLoop::push_tick_sample(const ForceResult& f, double t, Clock::Ns now) {
  TickSample& s = stages_->feed;
  s.tick = local_.tick;
  s.time_s = t;
  s.clock_ns = now.count();
  s.in_contact = f.in_contact;
  s.surface = f.in_contact ? f.surface : -1;
  s.normal = f.contact_normal;
  const double radius = stages_->proxy->probe_radius_mm();
  s.proxy_mm = f.in_contact ? f.proxy_mm - radius * f.contact_normal : f.proxy_mm;
  s.velocity_mm_s = local_.velocity_mm_s;
  s.normal_force_n = f.in_contact ? std::max(0.0, glm::dot(f.force_n, f.contact_normal)) : 0.0;
  s.proxy_centre_mm = local_.proxy_mm;
  s.force_n = local_.force_n;
  s.field_force_n = local_.field_force_n;
  for (std::size_t i = 0; i < tick_feed_count_; ++i) tick_feeds_[i]->push(s);
  s = TickSample{};
}

void HapticLoop::add_tick_feed(TickFeed* feed) {
  // Checked in release builds too: a third feed would be written past tick_feeds_ on every tick.
  if (feed == nullptr || tick_feed_count_ >= kMaxTickFeeds || thread_.joinable()) {
    std::fprintf(stderr, "HapticLoop::add_tick_feed: null, more than %zu feeds, or after start()\n", kMaxTickFeeds);
    std::abort();
  }
  tick_feeds_[tick_feed_count_++] = feed;
}

double HapticLoop::session_time_s(Clock::Ns now) const {
  return params_.start_time_s + static_cast<double>((now - start_).count()) * 1e-9;
}

// T of the filter = the measured tick period: a late tick's is longer, the one after it
// shorter (the grid does not move), and after a stall the missed ticks are skipped
// (tick_schedule.h), so T spans the stall. Clamped so a long stall (debugger, suspend) cannot
// blow up the prediction.
double HapticLoop::tick_period_s(Clock::Ns now) const {
  const double nominal = static_cast<double>(period_.count()) * 1e-9;
  return local_.tick == 0 ? nominal : std::clamp(static_cast<double>((now - last_tick_).count()) * 1e-9, 1e-5, 0.05);
}

// Read the device: recorded, sanitized, filtered.
void HapticLoop::read_device(double t, double dt, Clock::Ns now) {
  const DeviceSample raw = device_.read(t);
  if (recorder_ != nullptr) recorder_->append(raw);
  // The device put its hand somewhere new itself (a clutch): no motion of the person's, so the
  // filter starts afresh at this sample instead of taking the jump for a velocity.
  if (raw.valid && raw.placements != placements_seen_) {
    placements_seen_ = raw.placements;
    restart_filter_now();
  }
  if (auto s = sanitizer_.filter(raw)) {
    // A device polled slower than 1 kHz (the mouse: once per rendered frame) repeats its last
    // sample until the next poll. A repeat is no new measurement: feeding it would pull the
    // velocity to zero between polls and jerk it up at each one; predict instead.
    const bool repeat = have_fed_ && s->time_s == last_fed_.time_s && s->position_mm == last_fed_.position_mm;
    if (repeat) kalman_.predict(dt);
    else kalman_.step(dt, s->position_mm);
    last_fed_ = *s;
    have_fed_ = true;
    local_.device_mm = s->position_mm;
    local_.buttons = s->buttons;
    local_.sample_clock_ns = now.count();
    local_.have_sample = true;
  } else if (kalman_.initialized()) {
    kalman_.step(dt, kalman_.position() + dt * kalman_.velocity());  // hold: coast on the prediction
  }
}

// The proxy model's step becomes the state's contact readouts; a contact that starts or ends
// is an event.
void HapticLoop::take_proxy_step(const ForceResult& f, double t) {
  if (f.in_contact != local_.in_contact) {
    HapticEvent e = make_event(f.in_contact ? EventKind::contact_start : EventKind::contact_end, local_.tick, t);
    e.surface = f.in_contact ? f.surface : local_.contact_surface;
    e.position_mm = f.proxy_mm;
    // Approach speed: the hand's speed against the force (the force points out of the
    // surface); the whole speed when the first tick's force is still zero.
    const double fn = glm::length(f.force_n);
    e.value = fn > 0.0 ? std::max(0.0, -glm::dot(local_.velocity_mm_s, f.force_n / fn))
                       : glm::length(local_.velocity_mm_s);
    if (!f.in_contact) e.value = 0.0;
    events_.push(e);
    // Marks the start even with no measurable approach speed (its transient is then ~0).
    if (f.in_contact) stages_->feed.impact_mm_s = std::max(e.value, 1e-6);
  }
  local_.contact_surface = f.surface;
  local_.local_facets = f.facets_visited;
  local_.proxy_mm = f.proxy_mm;
  local_.force_n = f.force_n;
  local_.penetration_mm = f.penetration_mm;
  local_.in_contact = f.in_contact;
  local_.proxy_catching_up = f.catching_up;
  if (!stages_->proxy->sheet(local_.sheet_surface, local_.sheet_w4)) local_.sheet_surface = -1;
}

// The servo loop after the filter: move the workspace, the effects on the probe, the proxy
// model, the effects on the hand and the workspace's roll, then the force.
void HapticLoop::servo(double t, double dt, Clock::Ns now) {
  Stages& s = *stages_;
  local_.position_mm = kalman_.position();
  local_.velocity_mm_s = kalman_.velocity();
  const bool travel = !navigation_held_.load(std::memory_order_relaxed);
  const glm::dvec3 wall = s.workspace.navigate(last_fed_.position_mm, dt, local_, travel);
  EffectTick fx{s.god_object(), local_, s.feed, events_, t, dt};
  const glm::dvec3 on_probe = wall + s.effects.on_probe(fx);
  const ForceResult f = s.proxy->step(params_.forces, local_.position_mm, local_.velocity_mm_s, t, on_probe);
  local_.field_force_n = on_probe;
  take_proxy_step(f, t);
  fx.contact = &f;
  s.effects.on_hand(fx, local_.force_n);
  glm::dvec3 tether(0.0);
  if (s.workspace.roll(s.god_object(), view_axes_, dt, local_, tether)) local_.force_n += tether;
  local_.force_scale = schedule_.force_scale(now);
  local_.force_n *= local_.force_scale;
  device_.write_force(s.workspace.to_device(local_.force_n));  // felt in the device's own workspace
  if (tick_feed_count_ > 0) push_tick_sample(f, t, now);
}

void HapticLoop::tick(Clock::Ns now) {
  if (swap_pending_.load(std::memory_order_acquire)) adopt_pending_scene(now);
  if (home_pending_.exchange(false, std::memory_order_acq_rel)) stages_->workspace.home();
  const double dt = tick_period_s(now);
  update_rate(now);
  const double t = session_time_s(now);
  read_device(t, dt, now);
  if (local_.have_sample) servo(t, dt, now);
  local_.time_s = t;
  local_.rejected = sanitizer_.counts();
  ++local_.tick;
  state_.publish(local_);
}

}  // namespace ps
