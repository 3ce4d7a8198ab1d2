#include "haptics/haptic_loop.h"

#include "haptics/rtkit.h"

#include <pthread.h>
#include <sched.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <cassert>
#include <cerrno>
#include <cmath>
#include <cstring>

namespace ps {

HapticLoop::HapticLoop(Device& device, Clock& clock, const HapticLoopParams& params,
                       const world::HapticScene* scene)
    : device_(device), clock_(clock), params_(params),
      period_(static_cast<std::int64_t>(std::llround(1e9 / params.rate_hz))),
      schedule_(period_, params.schedule),
      sanitizer_(params.sanitizer), kalman_(params.kalman), periods_us_(params.keep_periods),
      // A HUD window is 1 s of ticks (missed ticks are skipped, never run back to back); room
      // for 2 s all the same (beyond that the HUD's p99 skips samples).
      window_jitter_us_(2 * static_cast<std::size_t>(std::ceil(params.rate_hz)) + 16) {
  if (scene != nullptr) {
    god_.emplace(*scene);
    bodies_ = world::BodySet(scene->bodies(), scene->fields().gravity_mm_s2());
    buttons_ = world::ButtonSet(scene->button_shapes(), scene->probe_radius_mm(), params.forces.coupling_n_per_mm);
  }
  clock_.set_wake_spin(std::chrono::microseconds(std::max<std::int64_t>(params.wake_spin_us, 0)));
}

HapticLoop::~HapticLoop() { stop(); }

namespace {

// sched_setattr(2) has no glibc wrapper; the struct is the kernel's (include/uapi/linux/sched/types.h).
struct SchedAttr {
  std::uint32_t size;
  std::uint32_t sched_policy;
  std::uint64_t sched_flags;
  std::int32_t sched_nice;
  std::uint32_t sched_priority;
  std::uint64_t sched_runtime, sched_deadline, sched_period;
  std::uint32_t sched_util_min, sched_util_max;
};

// Asks for a shorter EEVDF slice for the calling thread (SCHED_OTHER, nice unchanged). Returns
// 0 or an errno; kernels before 6.12 accept it and ignore the runtime.
int request_slice(std::int64_t slice_us) {
  SchedAttr attr{};
  attr.size = sizeof attr;
  attr.sched_policy = SCHED_OTHER;
  attr.sched_nice = getpriority(PRIO_PROCESS, 0);
  attr.sched_runtime = static_cast<std::uint64_t>(slice_us) * 1000u;
  return syscall(SYS_sched_setattr, 0, &attr, 0u) == 0 ? 0 : errno;
}

}  // namespace

void HapticLoop::start() {
  stop_.store(false);
  std::atomic<pid_t> tid{0};
  thread_ = std::thread([this, &tid] {
    tid.store(static_cast<pid_t>(syscall(SYS_gettid)));
    tid.notify_one();
    pthread_setname_np(pthread_self(), "ps-haptic");  // shows in top -H, ps -L, /proc/<pid>/task/*/comm
    if (params_.sched_slice_us > 0) slice_error_.store(request_slice(params_.sched_slice_us));
    if (params_.timer_slack_ns > 0) prctl(PR_SET_TIMERSLACK, static_cast<unsigned long>(params_.timer_slack_ns), 0, 0, 0);
    while (!stop_.load(std::memory_order_relaxed)) scheduled_tick();
  });
  tid.wait(0);
  if (params_.realtime_priority > 0) request_realtime(tid.load());
}

// SCHED_FIFO when this process may (CAP_SYS_NICE, RLIMIT_RTPRIO), else SCHED_RR through
// RealtimeKit where the system runs it (haptics/rtkit.h), else normal priority, saying why.
void HapticLoop::request_realtime(pid_t tid) {
  sched_param sp{};
  sp.sched_priority = std::min(params_.realtime_priority, 99);
  const int err = pthread_setschedparam(thread_.native_handle(), SCHED_FIFO, &sp);
  if (err == 0) {
    priority_ = "SCHED_FIFO " + std::to_string(sp.sched_priority);
    return;
  }
  const Result<int> rr = rtkit::make_thread_realtime(tid, sp.sched_priority);
  priority_ = rr ? "SCHED_RR " + std::to_string(rr.value()) + " (RealtimeKit)"
                 : std::string("normal (SCHED_FIFO refused: ") + std::strerror(err) + "; " + rr.error().message + ")";
}

std::string HapticLoop::scheduling() const {
  std::string out = priority_;
  if (params_.sched_slice_us > 0) {
    const int err = slice_error_.load();
    out += err == 0 ? ", slice " + std::to_string(params_.sched_slice_us) + " us"
                    : std::string(", slice refused (") + std::strerror(err) + ")";
  }
  out += params_.timer_slack_ns > 0 ? ", timer slack " + std::to_string(params_.timer_slack_ns) + " ns"
                                    : std::string(", timer slack: kernel default");
  out += ", wake spin " + std::to_string(std::max<std::int64_t>(params_.wake_spin_us, 0)) + " us";
  return out;
}

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
  HapticEvent e;
  e.kind = EventKind::tick_stall;
  e.tick = local_.tick;
  e.time_s = params_.start_time_s + static_cast<double>((now - start_).count()) * 1e-9;
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

void HapticLoop::replace_scene(std::shared_ptr<const world::HapticScene> scene, std::string_view label,
                               std::optional<glm::dvec3> place_hand_mm) {
  std::shared_ptr<const world::HapticScene> drop;
  {
    std::lock_guard<std::mutex> lock(swap_mutex_);
    drop = std::move(retired_);  // released here, on the caller's thread
    pending_ = std::move(scene);
    pending_label_.assign(label);
    pending_place_ = place_hand_mm;
    pending_place_normal_.reset();
    swap_pending_.store(true, std::memory_order_release);
  }
}

void HapticLoop::place_hand(const glm::dvec3& hand_mm, const glm::dvec3& normal, const glm::dvec3& surface_normal) {
  std::lock_guard<std::mutex> lock(swap_mutex_);
  pending_place_ = hand_mm;
  pending_place_normal_ = normal;
  pending_place_surface_ = surface_normal;
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
  } else {
    kalman_ = Kalman3(params_.kalman);
    have_fed_ = false;
  }
  sanitizer_.restart();  // else it would clamp the placed sample into a 5 m/s ramp the filter takes for speed
  if (god_) god_->reset(hand_mm);
  local_.proxy_mm = hand_mm;
}

const world::HapticScene* HapticLoop::scene() const { return god_ ? &god_->scene() : nullptr; }

void HapticLoop::adopt_pending_scene(Clock::Ns now) {
  // try_lock: the caller holds the mutex only to swap two pointers; if it is in there now, the
  // next tick adopts the scene instead of this one waiting.
  std::unique_lock<std::mutex> lock(swap_mutex_, std::try_to_lock);
  if (!lock.owns_lock()) return;
  swap_pending_.store(false, std::memory_order_relaxed);
  if (!pending_) {  // a placement alone (place_hand)
    if (pending_place_) place(*pending_place_, pending_place_normal_);
    pending_place_.reset();
    pending_place_normal_.reset();
    return;
  }
  const bool had_proxy = god_ && god_->initialized();
  glm::dvec3 proxy = local_.proxy_mm;
  god_.emplace(*pending_);  // GodObject holds no heap memory: nothing is freed on this thread
  crossing_.reset();
  if (pending_place_) {
    proxy = *pending_place_;
    place(proxy);
    pending_place_.reset();
    pending_place_normal_.reset();
  } else if (had_proxy) {
    god_->reset(proxy);
  }
  // The new scene's bodies start afresh (a rare event: the vectors' old storage is freed here).
  bodies_ = world::BodySet(pending_->bodies(), pending_->fields().gravity_mm_s2());
  buttons_ = world::ButtonSet(pending_->button_shapes(), pending_->probe_radius_mm(),
                              params_.forces.coupling_n_per_mm, true);  // nothing fires until the probe has left
  local_.flags = 0;  // flags are the scene's: a new scene starts with all of them off
  view_ = fourd::ViewPose{};  // and its own view
  roll_.reset();
  retired_ = std::move(scene_owned_);
  scene_owned_ = std::move(pending_);
  HapticEvent e;
  e.kind = EventKind::scene_switched;
  e.tick = local_.tick;
  e.time_s = params_.start_time_s + static_cast<double>((now - start_).count()) * 1e-9;
  e.position_mm = proxy;
  e.set_label(pending_label_);
  events_.push(e);
}

// The scene's fields at the proxy (last tick's: the probe that is in the field) and the bodies'
// springs, stepped one tick; floor impacts become events.
// Compares the published live charges with the adopted ones by id: one charge_added or
// charge_removed event per difference, with this tick's time.
void HapticLoop::adopt_live_charges(double t) {
  const LiveCharges now = live_charges_.read();
  auto has = [](const LiveCharges& set, std::uint32_t id) {
    for (int i = 0; i < set.count; ++i)
      if (set.id[i] == id) return i;
    return -1;
  };
  auto raise = [&](EventKind kind, const LiveCharges& set, int i) {
    HapticEvent e;
    e.kind = kind;
    e.tick = local_.tick;
    e.time_s = t;
    e.index = static_cast<int>(set.id[i]);
    e.value = set.charge_n_mm2[i];
    e.position_mm = set.position[i];
    events_.push(e);
  };
  for (int i = 0; i < adopted_charges_.count; ++i)
    if (has(now, adopted_charges_.id[i]) < 0) raise(EventKind::charge_removed, adopted_charges_, i);
  for (int i = 0; i < now.count; ++i)
    if (has(adopted_charges_, now.id[i]) < 0) raise(EventKind::charge_added, now, i);
  adopted_charges_ = now;
}

// The buttons under the probe: their springs join the force on the probe; a button that gives
// way raises button_fired (label: its action as written) and, for a flag action, toggles the
// flag and raises flag_toggled. A scene action is carried out by the event's consumer.
void HapticLoop::press_buttons(const glm::dvec3& anchor, double t, glm::dvec3& force) {
  if (buttons_.size() == 0) return;
  const world::HapticScene& scene = god_->scene();
  // The hand as the device gives it, not the Kalman estimate: after a scene switch the filter
  // sweeps from the old scene's mapping of the pointer to the new one over some ticks, and that
  // sweep can pass over a button clear of its face like an approach (run fired the panel's
  // Weight button 20 ms after a Backspace). The raw position jumps instead.
  const world::ButtonStepResult r = buttons_.step(anchor, local_.device_mm);
  force += r.force_n;
  local_.button_pressed = r.pressed;
  local_.button_depth_mm = r.depth_mm;
  for (int k = 0; k < r.fired_count; ++k) {
    const std::size_t i = static_cast<std::size_t>(r.fired[static_cast<std::size_t>(k)]);
    const Button& b = scene.buttons()[i];
    HapticEvent e;
    e.kind = EventKind::button_fired;
    e.tick = local_.tick;
    e.time_s = t;
    e.surface = scene.button_shapes()[i].surface;
    e.index = static_cast<int>(i);
    e.value = b.travel_mm;
    e.position_mm = anchor;
    e.set_label(b.action);
    events_.push(e);
    feed_sample_.click = true;
    if (b.action_kind != ButtonActionKind::kFlag || b.flag < 0) continue;
    local_.flags ^= 1u << static_cast<unsigned>(b.flag);
    e.kind = EventKind::flag_toggled;
    e.value = (local_.flags >> static_cast<unsigned>(b.flag)) & 1u;
    e.set_label(b.action_target);
    events_.push(e);
  }
}

glm::dvec3 HapticLoop::world_forces(double t, double dt) {
  const world::HapticScene& scene = god_->scene();
  const glm::dvec3 anchor = god_->initialized() ? god_->proxy() : local_.position_mm;
  glm::dvec3 f = scene.fields().empty() ? glm::dvec3(0.0) : scene.fields().force_n(anchor, local_.velocity_mm_s, t);
  adopt_live_charges(t);
  for (int i = 0; i < adopted_charges_.count; ++i)
    f += world::FieldSet::charge_force_n(anchor, adopted_charges_.position[i], adopted_charges_.charge_n_mm2[i],
                                         adopted_charges_.softening_mm);
  press_buttons(anchor, t, f);
  local_.body_count = static_cast<int>(bodies_.size());
  if (bodies_.size() == 0) return f;
  const world::BodyStepResult r = bodies_.step(anchor, dt);
  f += r.force_on_proxy_n;
  for (std::size_t i = 0; i < bodies_.size(); ++i) local_.body_mm[i] = bodies_.position(i);
  for (int k = 0; k < r.impact_count; ++k) {
    HapticEvent e;
    e.kind = EventKind::body_impact;
    e.tick = local_.tick;
    e.time_s = t;
    e.index = r.impacts[k].body;
    e.value = r.impacts[k].speed_mm_s;
    e.position_mm = r.impacts[k].position_mm;
    events_.push(e);
  }
  return f;
}

glm::dvec3 HapticLoop::navigate(double dt) {
  const world::HapticScene& scene = god_->scene();
  const Navigation& nav = scene.navigation();
  if (!nav.enabled && !scene.any_fourd_roll()) return glm::dvec3(0.0);  // workspace = world
  const glm::dvec3 hand = local_.position_mm;  // workspace
  glm::dvec3 v(0.0), wall(0.0);
  if (nav.enabled) {
    // A rate control with the box as its dead zone, on the device's own position: the Kalman
    // filter overshoots a step (a mouse jumping from the window's edge back to its centre), and
    // the view must stop when the hand is back inside, not travel on (38 mm back in `run`).
    const glm::dvec3 at = last_fed_.position_mm;
    const glm::dvec3 half = 0.5 * nav.box_size_mm;
    const glm::dvec3 past = at - glm::clamp(at, nav.box_center - half, nav.box_center + half);
    v = nav.speed_mm_s_per_mm * past;
    const double speed = glm::length(v);
    if (speed > nav.max_speed_mm_s) v *= nav.max_speed_mm_s / speed;
    view_.offset += view_.rotation * v * dt;
    wall = -nav.wall_n_per_mm * past;
  }
  local_.view_offset_mm = view_.offset;
  local_.view_rotation = view_.rotation;
  local_.position_mm = view_.to_world(hand);
  local_.device_mm = view_.to_world(last_fed_.position_mm);
  // The hand's speed over the world: the texture sees the craft move.
  local_.velocity_mm_s = view_.rotation * (local_.velocity_mm_s + v);
  return view_.rotation * wall;
}

glm::dvec3 HapticLoop::roll(double dt) {
  if (!god_->scene().any_fourd_roll()) return glm::dvec3(0.0);
  const world::Contact* c = god_->sheet_contact();
  const fourd::RollParams p = c != nullptr ? god_->scene().fourd_roll(c->surface) : fourd::RollParams{};
  fourd::RollContact rc;
  if (c != nullptr && p.on) {
    rc.on_sheet = true;
    rc.facet = c->fourd_facet;
    rc.point = c->point;
    rc.normal = c->normal;
  }
  const PublishedViewAxes published = view_axes_.read();
  const fourd::ViewAxes& axes = published.valid ? published.axes : god_->scene().view_axes();
  roll_.step(p, axes, rc, dt, view_);
  local_.view_offset_mm = view_.offset;
  local_.view_rotation = view_.rotation;
  local_.roll_facet = roll_.facet();
  if (!rc.on_sheet) return glm::dvec3(0.0);
  return fourd::RollingManifold::tether_force(p, axes, view_, local_.proxy_mm);
}

// Seed 000 §5: a cue each time the proxy's contact point on a surface embedded in 4D passes
// through another sheet of it (docs/fourd.md); value +1 in front of it, -1 behind it.
void HapticLoop::detect_crossing(double t) {
  glm::dvec3 point(0.0);
  int surface = -1;
  double w = 0.0;
  const fourd::FourdTouch* touch = nullptr;
  if (god_ && god_->sheet(surface, w, &point)) touch = god_->scene().fourd_touch(surface);
  if (touch == nullptr) {
    crossing_.reset();
    return;
  }
  const int c = crossing_.update(*touch, point, w, touch->window(w, w));
  if (c == 0) return;
  HapticEvent e;
  e.kind = EventKind::sheet_crossing;
  e.tick = local_.tick;
  e.time_s = t;
  e.surface = surface;
  e.value = c;
  e.position_mm = point;
  events_.push(e);
}

glm::dvec3 HapticLoop::suggestion_force(double dt) {
  glm::dvec3 point(0.0);
  int surface = -1;
  double w = 0.0;
  if (!god_ || !god_->sheet(surface, w, &point)) {
    have_sheet_point_ = false;
    return glm::dvec3(0.0);
  }
  const fourd::SuggestionParams p = god_->scene().fourd_suggestion(surface);
  const glm::dvec3 v = have_sheet_point_ && dt > 0.0 ? (point - last_sheet_point_) / dt : glm::dvec3(0.0);
  last_sheet_point_ = point;
  have_sheet_point_ = true;
  if (!p.on()) return glm::dvec3(0.0);
  const glm::dvec3 n = glm::normalize(local_.proxy_mm - point);  // the facet's normal on the proxy's side
  glm::dvec3 p_des, v_des;
  fourd::desired_state(p, point, local_.velocity_mm_s, n, p_des, v_des);
  return fourd::force_suggestion_n(p, p_des, point, v_des, v, n);
}

// The tick's record for the vibration signal: the contact point on the surface (proxy centre
// minus the probe radius along the normal), the normal and the force along it.
void HapticLoop::push_tick_sample(const ForceResult& f, double t, Clock::Ns now) {
  TickSample& s = feed_sample_;
  s.tick = local_.tick;
  s.time_s = t;
  s.clock_ns = now.count();
  s.in_contact = f.in_contact;
  s.surface = f.in_contact ? f.surface : -1;
  s.normal = f.contact_normal;
  const double radius = god_ ? god_->scene().probe_radius_mm() : surface_.read().probe_radius_mm;
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
  assert(feed != nullptr && tick_feed_count_ < kMaxTickFeeds && "HapticLoop::add_tick_feed: null or too many feeds");
  assert(!thread_.joinable() && "HapticLoop::add_tick_feed: before start()");
  tick_feeds_[tick_feed_count_++] = feed;
}

void HapticLoop::tick(Clock::Ns now) {
  if (swap_pending_.load(std::memory_order_acquire)) adopt_pending_scene(now);
  if (home_pending_.exchange(false, std::memory_order_acq_rel)) {
    view_ = fourd::ViewPose{};
    roll_.reset();
  }
  // T of the filter = the measured tick period: a late tick's is longer, the one after it
  // shorter (the grid does not move), and after a stall the missed ticks are skipped
  // (tick_schedule.h), so T spans the stall. Clamped so a long stall (debugger, suspend) cannot
  // blow up the prediction.
  const double nominal = static_cast<double>(period_.count()) * 1e-9;
  const double dt = local_.tick == 0 ? nominal
                                     : std::clamp(static_cast<double>((now - last_tick_).count()) * 1e-9, 1e-5, 0.05);
  update_rate(now);
  const double t = params_.start_time_s + static_cast<double>((now - start_).count()) * 1e-9;
  const DeviceSample raw = device_.read(t);
  if (recorder_ != nullptr) recorder_->append(raw);
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
  if (local_.have_sample) {
    local_.position_mm = kalman_.position();
    local_.velocity_mm_s = kalman_.velocity();
    glm::dvec3 field_force(0.0);
    if (god_) field_force = navigate(dt);
    if (god_) field_force += world_forces(t, dt);
    const ForceResult f = god_ ? compute_proxy_force(params_.forces, *god_, local_.position_mm, local_.velocity_mm_s, t,
                                                     field_force)
                               : compute_force(params_.forces, surface_.read(), local_.position_mm,
                                               local_.velocity_mm_s, local_.proxy_mm, t);
    local_.field_force_n = field_force;
    if (f.in_contact != local_.in_contact) {
      HapticEvent e;
      e.kind = f.in_contact ? EventKind::contact_start : EventKind::contact_end;
      e.tick = local_.tick;
      e.time_s = t;
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
      if (f.in_contact) feed_sample_.impact_mm_s = std::max(e.value, 1e-6);
    }
    local_.contact_surface = f.surface;
    local_.local_facets = f.facets_visited;
    local_.proxy_mm = f.proxy_mm;
    local_.force_n = f.force_n;
    local_.penetration_mm = f.penetration_mm;
    local_.in_contact = f.in_contact;
    if (!god_ || !god_->sheet(local_.sheet_surface, local_.sheet_w4)) local_.sheet_surface = -1;
    detect_crossing(t);
    if (f.in_contact) local_.force_n += suggestion_force(dt);
    if (god_) local_.force_n += roll(dt);
    local_.force_scale = schedule_.force_scale(now);
    local_.force_n *= local_.force_scale;
    // The device feels the force in its own workspace.
    device_.write_force(glm::transpose(view_.rotation) * local_.force_n);
    if (tick_feed_count_ > 0) push_tick_sample(f, t, now);
  }
  local_.time_s = t;
  local_.rejected = sanitizer_.counts();
  ++local_.tick;
  state_.publish(local_);
}

}  // namespace ps
