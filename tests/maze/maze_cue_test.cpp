// Each cue of the maze measured where a participant meets it: the haptic loop (fake clock, the
// same code `maze` and `replay` run) on the generated scene of pass 1, a scripted device in the
// cue's room, the numbers read off the loop's per-tick force trace. No GL (the pictures are
// maze_gl_test's).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "devices/sample_log.h"
#include "haptics/haptic_loop.h"
#include "maze/maze.h"
#include "maze/maze_script.h"
#include "maze/maze_session.h"
#include "maze_test_util.h"

namespace ps::maze {
namespace {

struct CueSetup {
  MazeDesc desc;
  Route route = draw_route(3);
  RoomGeometry g;
  MazeScene scene;
  std::shared_ptr<const world::HapticScene> haptic;
  // The centre (x, y) of `cue`'s room in pass 1.
  glm::dvec3 room(Cue cue) const {
    const auto order = route.order(0);
    for (int i = 0; i < kRoomsPerPass; ++i)
      if (order[static_cast<std::size_t>(i)] == cue) return {0.0, g.center_y(i), 0.0};
    return glm::dvec3(NAN);
  }
};

CueSetup setup(bool cues) {
  CueSetup s;
  auto d = load_maze_desc(test::maze_file());
  EXPECT_TRUE(d) << d.error().message;
  s.desc = d.value();
  s.g = room_geometry(s.desc);
  auto scene = generate_scene(s.desc, s.route, cues, 0);
  EXPECT_TRUE(scene) << scene.error().message;
  s.scene = std::move(scene.value());
  s.haptic = build_haptic(s.scene).value();
  return s;
}

// Runs the loop over `device` for its whole duration; every tick's state.
std::vector<HapticState> trace(const CueSetup& s, Device& device) {
  FakeClock clock;
  HapticLoop loop(device, clock, HapticLoopParams{}, s.haptic.get());
  std::vector<HapticState> out;
  const auto ticks = static_cast<std::uint64_t>(device.duration_s() * 1000.0) + 1;
  for (std::uint64_t k = 0; k < ticks; ++k) {
    loop.run_ticks(1);
    out.push_back(loop.state().read());
  }
  return out;
}

std::unique_ptr<LogDevice> scripted(std::initializer_list<std::pair<double, glm::dvec3>> keys) {
  std::vector<DeviceSample> samples;
  for (const auto& [t, p] : keys) samples.push_back({t, p, 0u, true});
  return std::make_unique<LogDevice>(samples, true, "scripted");
}

// A hand on a force device: a point mass with its own damping, pushed along +y by a constant
// force, moved by that push, its damping and the force the loop writes back.
class PushedHand final : public Device {
 public:
  PushedHand(glm::dvec3 start, double seconds) : x_(start), seconds_(seconds) {}
  DeviceSample read(double now_s) override {
    const double dt = now_s - t_;
    if (dt > 0.0) {
      const glm::dvec3 f = glm::dvec3(0.0, kPushN, 0.0) + force_ - kHandDampingNsPerMm * v_;
      v_ += 1000.0 * f / kMassKg * dt;  // N / kg = m/s^2 = 1000 mm/s^2
      x_ += v_ * dt;
      t_ = now_s;
    }
    return {now_s, x_, 0u, true};
  }
  void write_force(const glm::dvec3& f) override { force_ = f; }
  double duration_s() const override { return seconds_; }
  std::string name() const override { return "pushed hand"; }
  static constexpr double kPushN = 0.4, kHandDampingNsPerMm = 0.004, kMassKg = 0.05;

 private:
  glm::dvec3 x_, v_{0.0}, force_{0.0};
  double t_ = 0.0, seconds_;
};

// The hand's speed at the end of a 0.5 s push that starts 50 mm before the room's centre.
double pushed_speed(const CueSetup& s, Cue cue) {
  PushedHand hand(s.room(cue) + glm::dvec3(0.0, -50.0, s.desc.probe_radius_mm + 1.0), 0.5);
  const std::vector<HapticState> t = trace(s, hand);
  return t.back().velocity_mm_s.y;
}

// (2) Viscosity: a constant push on a force device settles at F / (d + b) in the viscous room
// and F / d in the dummy room (d: the hand's own damping), so the cue slows it by d / (d + b) =
// 0.5 here; and on a scripted constant-speed stroke the field force is -b v. Tolerance 2 %:
// after 0.5 s the push has settled to within e^-(0.5 / tau), tau = m / (d + b) = 6 ms, of its
// terminal speed; what is left is the Kalman filter's lag and the 1 ms steps.
TEST(MazeCueTest, ViscositySlowsAConstantPushByTheExpectedFactor) {
  const CueSetup s = setup(true);
  const double b = s.desc.viscosity_n_s_per_mm, d = PushedHand::kHandDampingNsPerMm;
  const double dummy = pushed_speed(s, Cue::kNone), viscous = pushed_speed(s, Cue::kViscosity);
  EXPECT_NEAR(dummy, PushedHand::kPushN / d, 0.02 * PushedHand::kPushN / d);
  EXPECT_NEAR(viscous / dummy, d / (d + b), 0.02 * d / (d + b)) << "dummy " << dummy << " viscous " << viscous;
  RecordProperty("viscosity_speed_ratio", std::to_string(viscous / dummy));
  // The stroke: 60 mm/s along +y through the room's middle; force over the middle 40 mm.
  const glm::dvec3 c = s.room(Cue::kViscosity) + glm::dvec3(20.0, 0.0, s.desc.probe_radius_mm + 1.0);
  auto dev = scripted({{0.0, c - glm::dvec3(0, 45, 0)}, {1.5, c + glm::dvec3(0, 45, 0)}});
  const std::vector<HapticState> t = trace(s, *dev);
  double ratio = 0.0;
  int n = 0;
  for (const HapticState& st : t)
    if (std::abs(st.proxy_mm.y - c.y) < 20.0) ratio += -st.field_force_n.y / st.velocity_mm_s.y, ++n;
  ASSERT_GT(n, 100);
  EXPECT_NEAR(ratio / n, b, 1e-3 * b);  // F = -b v exactly, v the filtered velocity the law uses
}

// (4) The hidden sphere: a stroke 1 mm over the floor (the sphere's centre height, as the
// participant travels), 12 mm beside its centre, is pushed aside by the overlap, radius + probe
// radius - 12 = 8 mm (1 %: the stroke is slow, 60 mm/s, so the god-object settles on the sphere
// each tick), touching the hidden surface, and still gets past it; with cues off the same stroke
// goes straight (the proxy on the line within 1e-6 mm).
// The picture (no pixel shows the sphere): maze_gl_test.
TEST(MazeCueTest, HiddenSphereDeflectsThePath) {
  for (const bool cues : {true, false}) {
    const CueSetup s = setup(cues);
    const glm::dvec3 c = s.room(Cue::kHiddenSphere) + glm::dvec3(s.desc.hidden_offset_mm, s.desc.hidden_height_mm) +
                         glm::dvec3(12.0, 0.0, 0.0);
    auto dev = scripted({{0.0, c - glm::dvec3(0, 45, 0)}, {1.5, c + glm::dvec3(0, 45, 0)}});
    double off_line = 0.0;
    int hidden_contact = 0;
    const std::vector<HapticState> t = trace(s, *dev);
    for (const HapticState& st : t) {
      off_line = std::max(off_line, std::abs(st.proxy_mm.x - c.x));
      hidden_contact += contact_kind(s.scene, st) == static_cast<int>(SurfaceKind::kHidden);
    }
    EXPECT_NEAR(t.back().proxy_mm.y, c.y + 45.0, 1e-3) << "the stroke gets past";
    if (cues) {
      RecordProperty("hidden_sphere_deflection_mm", std::to_string(off_line));
      const double overlap = s.desc.hidden_radius_mm + s.desc.probe_radius_mm - 12.0;
      EXPECT_NEAR(off_line, overlap, 0.01 * overlap);
      EXPECT_GT(hidden_contact, 100);
    } else {
      EXPECT_LT(off_line, 1e-6);
      EXPECT_EQ(hidden_contact, 0);
    }
  }
}

// (5) The external force: the probe held still in the room for 2 s; the force trace points
// along the configured direction only (other components 0 to 1e-12 N), peaks at the configured
// amplitude (1e-4: the 1 ms sampling of a 2 Hz sine misses its peak by < 1 - cos(2 pi 2 / 1000
// / 2) ~ 2e-5), and its zero crossings give the configured frequency (1 %: crossings are timed
// to the 1 ms tick, over ~2 s).
TEST(MazeCueTest, ExternalForceDirectionAndFrequencyFromTheTrace) {
  const CueSetup s = setup(true);
  const glm::dvec3 p = s.room(Cue::kExternalForce) + glm::dvec3(0.0, -30.0, s.desc.probe_radius_mm + 1.0);
  auto dev = scripted({{0.0, p}, {2.2, p}});
  const std::vector<HapticState> t = trace(s, *dev);
  const glm::dvec3 dir = glm::normalize(s.desc.external_fluctuation_n);
  double peak = 0.0, first = -1.0, last = -1.0;
  int crossings = 0;
  for (std::size_t k = 1; k < t.size(); ++k) {
    const glm::dvec3 f = t[k].field_force_n;
    EXPECT_LT(glm::length(f - glm::dot(f, dir) * dir), 1e-12);
    peak = std::max(peak, std::abs(glm::dot(f, dir)));
    const double a = glm::dot(t[k - 1].field_force_n, dir), b = glm::dot(f, dir);
    if (t[k].time_s > 0.1 && (a < 0.0) != (b < 0.0)) {
      (first < 0.0 ? first : last) = t[k].time_s;
      ++crossings;
    }
  }
  EXPECT_NEAR(peak, glm::length(s.desc.external_fluctuation_n), 1e-4);
  ASSERT_GE(crossings, 6);
  const double f_measured = (crossings - 1) / (2.0 * (last - first));
  EXPECT_NEAR(f_measured, s.desc.external_frequency_hz, 0.01 * s.desc.external_frequency_hz);
  RecordProperty("external_frequency_hz", std::to_string(f_measured));
  // Out of contact the device gets the field's force itself (the pseudo-haptic coupling).
  EXPECT_LT(glm::length(t.back().force_n - t.back().field_force_n), 1e-9);
}

// (3) Elastic contacts: the device pressed 2 mm into the floor and held, in the elastic room
// and in the dummy room: the contact forces' ratio is the stiffness ratio (1e-6: both are the
// linear spring k r at rest, the damping term vanishes once the hand is still).
TEST(MazeCueTest, ElasticRoomPushesBackByTheStiffnessRatio) {
  const CueSetup s = setup(true);
  auto press = [&](Cue cue) {
    const glm::dvec3 c = s.room(cue) + glm::dvec3(20.0, -20.0, 0.0);
    auto dev = scripted({{0.0, c + glm::dvec3(0, 0, s.desc.probe_radius_mm + 3.0)},
                         {0.3, c + glm::dvec3(0, 0, s.desc.probe_radius_mm - 2.0)},
                         {0.8, c + glm::dvec3(0, 0, s.desc.probe_radius_mm - 2.0)}});
    const HapticState last = trace(s, *dev).back();
    EXPECT_TRUE(last.in_contact);
    EXPECT_EQ(contact_kind(s.scene, last), static_cast<int>(SurfaceKind::kFloor));
    return last.force_n.z;
  };
  const double elastic = press(Cue::kElastic), dummy = press(Cue::kNone);
  RecordProperty("elastic_force_n", std::to_string(elastic));
  RecordProperty("dummy_force_n", std::to_string(dummy));
  EXPECT_NEAR(dummy, 2.0 * s.desc.wall_stiffness_n_per_mm, 1e-3);  // k r, r = 2 mm (the filter's rest offset < 1 um)
  EXPECT_NEAR(elastic / dummy, s.desc.elastic_stiffness_n_per_mm / s.desc.wall_stiffness_n_per_mm, 1e-6);
}

// (1) The texture room's haptic texture: sliding 1 mm into the floor at 60 mm/s, the normal
// force swings by the wave's amplitude (its square wave adds +-A) in the texture room and stays
// smooth in the dummy room and, with cues off, in the texture room.
TEST(MazeCueTest, TextureRoomFloorIsFeltRough) {
  auto spread = [](const CueSetup& s, Cue cue) {
    const glm::dvec3 c = s.room(cue) + glm::dvec3(25.0, 0.0, s.desc.probe_radius_mm - 1.0);
    auto dev = scripted({{0.0, c + glm::dvec3(0, -30, 2)}, {0.2, c + glm::dvec3(0, -30, 0)},
                         {1.2, c + glm::dvec3(0, 30, 0)}});
    double lo = 1e9, hi = -1e9;
    for (const HapticState& st : trace(s, *dev))
      if (st.time_s > 0.5 && st.in_contact) lo = std::min(lo, st.force_n.z), hi = std::max(hi, st.force_n.z);
    return hi - lo;
  };
  const CueSetup on = setup(true), off = setup(false);
  const double a = on.desc.texture_amplitude_n;
  RecordProperty("texture_force_swing_n", std::to_string(spread(on, Cue::kTexture)));
  EXPECT_GT(spread(on, Cue::kTexture), 1.8 * a);  // a square wave of amplitude A swings by 2A
  EXPECT_LT(spread(on, Cue::kNone), 0.1 * a);
  EXPECT_LT(spread(off, Cue::kTexture), 0.1 * a);
}

// The cues as a session's log shows them: a scripted participant walks pass 1 (cues on, the
// correct exits) pressing 0.5 mm into the floor all the way, at 100 mm/s. Per room, from the
// branch lines of its log: the elastic room's mean force is 3 x the learning room's (1.5 / 0.5
// N/mm: both are the spring k r plus the same 5 % friction; 2 % for the corners of the path and
// the filter's settling at the room's entry), the texture room's largest force is the spring
// plus the wave's amplitude (0.25 + 0.15 N, 2 %), the viscous room's largest field force is b v
// (0.4 N; 10 %: the filtered velocity overshoots at the path's corners), the external force
// room's is the fluctuation's 1 N (1 %); the floor is touched the whole time in every room.
TEST(MazeCueTest, CuesShowInTheSessionLog) {
  auto d = load_maze_desc(test::maze_file());
  ASSERT_TRUE(d) << d.error().message;
  const Route route = draw_route(7);
  const std::string dir = test::temp_dir("cues_in_log");
  const double depth = 0.5;
  std::ofstream(dir + "/press.traj") << script_trajectory(d.value(), {correct_choices(route, 0)}, 100.0,
                                                          d->probe_radius_mm - depth);
  auto dev = open_log_device("trajectory:" + dir + "/press.traj");
  ASSERT_TRUE(dev) << dev.error().message;
  SessionOptions o;
  o.desc = d.value();
  o.route = route;
  o.info.participant = "press";
  o.info.cues = true;
  o.log_path = dir + "/session.jsonl";
  auto r = run_session(*dev.value(), o, nullptr, nullptr);
  ASSERT_TRUE(r) << r.error().message;
  ASSERT_EQ(r->reason, EndReason::kCriterion);
  std::map<std::string, nlohmann::json> room;
  for (const std::string& line : test::read_lines(o.log_path)) {
    const auto j = nlohmann::json::parse(line);
    if (j["type"] == "branch") room[j["cue"].get<std::string>()] = j;
  }
  ASSERT_EQ(room.size(), 6u);
  const double k = d->wall_stiffness_n_per_mm, ratio = d->elastic_stiffness_n_per_mm / k;
  const double mean_none = room["none"]["force_mean_n"], mean_elastic = room["elastic"]["force_mean_n"];
  RecordProperty("log_elastic_over_dummy", std::to_string(mean_elastic / mean_none));
  EXPECT_NEAR(mean_elastic / mean_none, ratio, 0.02 * ratio);
  EXPECT_NEAR(room["texture"]["force_max_n"].get<double>(), k * depth + d->texture_amplitude_n, 0.02 * (k * depth + d->texture_amplitude_n));
  EXPECT_NEAR(room["none"]["force_max_n"].get<double>(), k * depth * std::hypot(1.0, d->wall_dynamic_friction), 0.02 * k * depth);
  const double bv = d->viscosity_n_s_per_mm * 100.0;
  EXPECT_NEAR(room["viscosity"]["field_force_max_n"].get<double>(), bv, 0.1 * bv);
  EXPECT_NEAR(room["external_force"]["field_force_max_n"].get<double>(), glm::length(d->external_fluctuation_n), 0.01);
  for (const auto& [cue, j] : room) {
    EXPECT_NEAR(j["contact_s"]["floor"].get<double>(), j["room_time_s"].get<double>(), 0.002) << cue;
    EXPECT_EQ(j["contact_s"]["wall"].get<double>(), 0.0) << cue;
  }
}

}  // namespace
}  // namespace ps::maze
