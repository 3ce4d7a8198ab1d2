// [[fields]] and [[bodies]] on the haptic side against closed forms, and through the haptic loop
// (the coupling's lag and deflection, body impacts as events). No GL.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "devices/sample_log.h"
#include "haptics/haptic_loop.h"
#include "world/bodies.h"
#include "world/fields.h"
#include "world/haptic_scene.h"
#include "world_test_util.h"

namespace ps::world {
namespace {

Field charge(glm::dvec3 at, double q, double s) {
  Field f;
  f.type = FieldType::kCharge;
  f.position = at;
  f.charge_n_mm2 = q;
  f.softening_mm = s;
  return f;
}

// Coulomb's law summed by hand at sample points (1e-12 relative: the same double arithmetic
// in another order), zero exactly at a lone charge and bounded near it by the softened law's
// maximum q * 2 / (3 sqrt(3) s^2) at r = s / sqrt(2).
TEST(FieldSetTest, ChargesSumTheSoftenedCoulombLaw) {
  const std::vector<Field> fields = {charge({0, 0, 0}, 300, 2), charge({20, 0, 5}, -150, 1),
                                     charge({-10, 15, 0}, 80, 3)};
  const FieldSet set(fields);
  for (const glm::dvec3 p : {glm::dvec3(5, 5, 5), glm::dvec3(-3, 1, 12), glm::dvec3(19, 0.5, 5), glm::dvec3(40, -30, 2)}) {
    glm::dvec3 expect(0.0);
    for (const Field& f : fields) {
      const glm::dvec3 d = p - f.position;
      const double r2 = d.x * d.x + d.y * d.y + d.z * d.z + f.softening_mm * f.softening_mm;
      expect += f.charge_n_mm2 * d / std::pow(r2, 1.5);
    }
    const glm::dvec3 got = set.force_n(p, glm::dvec3(0.0), 0.0);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], expect[i], 1e-12 * std::max(1.0, glm::length(expect))) << i;
  }
  const FieldSet lone({charge({1, 2, 3}, 300, 2)});
  EXPECT_EQ(lone.force_n({1, 2, 3}, glm::dvec3(0.0), 0.0), glm::dvec3(0.0));
  const double bound = 300.0 * 2.0 / (3.0 * std::sqrt(3.0) * 4.0);
  for (double r = 0.01; r < 10.0; r *= 1.3)
    EXPECT_LE(glm::length(lone.force_n({1 + r, 2, 3}, glm::dvec3(0.0), 0.0)), bound * (1.0 + 1e-12)) << r;
  EXPECT_NEAR(glm::length(lone.force_n({1 + 2.0 / std::sqrt(2.0), 2, 3}, glm::dvec3(0.0), 0.0)), bound, 1e-12);
}

// F0 + F1 sin(2 pi f t) inside the (rotated) box region, nothing outside; -b v inside a viscous
// region only; gravity acts on bodies, not on the probe.
TEST(FieldSetTest, UniformViscousAndGravityFollowTheirLawsAndRegions) {
  Field u;
  u.type = FieldType::kUniform;
  u.force_n = {0.5, 0, 0};
  u.fluctuation_n = {0, 0.25, 0};
  u.frequency_hz = 2.0;
  u.bounded = true;
  u.center = {0, 0, 10};
  u.size_mm = {40, 10, 20};
  u.rotation_deg = {0, 0, 90};  // the long side now along y
  Field v;
  v.type = FieldType::kViscous;
  v.viscosity_n_s_per_mm = 0.01;
  v.bounded = true;
  v.center = {100, 0, 0};
  v.size_mm = {10, 10, 10};
  Field g;
  g.type = FieldType::kGravity;
  g.acceleration_mm_s2 = {0, 0, -9810};
  const FieldSet set({u, v, g});
  const glm::dvec3 vel(30, -10, 5);
  // t = 0.125 s at 2 Hz: sin(pi / 2) = 1 (1e-15: one rounding of sin near its peak).
  const glm::dvec3 in_u = set.force_n({0, 15, 10}, vel, 0.125);
  EXPECT_NEAR(in_u.x, 0.5, 1e-15);
  EXPECT_NEAR(in_u.y, 0.25, 1e-15);
  EXPECT_EQ(set.force_n({15, 0, 10}, vel, 0.125), glm::dvec3(0.0));  // outside the rotated box
  EXPECT_EQ(set.force_n({100, 4, -4}, vel, 0.0), -0.01 * vel);
  EXPECT_EQ(set.force_n({106, 0, 0}, vel, 0.0), glm::dvec3(0.0));
  EXPECT_EQ(set.gravity_mm_s2(), glm::dvec3(0, 0, -9810));
}

Body free_body() {
  Body b;
  b.mass_g = 50.0;
  b.spring_n_per_mm = 0.2;
  b.rest_length_mm = 20.0;
  b.floor = false;
  b.position = {0, 0, -35};  // 15 mm beyond the rest length
  return b;
}

// Energy of body i for a spring anchored at a: 1/2 m v^2 + 1/2 k (|x - a| - L)^2, in J.
double energy_j(const BodySet& s, std::size_t i, glm::dvec3 a) {
  const Body& b = s.spec(i);
  const double v = glm::length(s.velocity(i)) * 1e-3;
  const double stretch = (glm::length(s.position(i) - a) - b.rest_length_mm) * 1e-3;
  return 0.5 * b.mass_g * 1e-3 * v * v + 0.5 * b.spring_n_per_mm * 1e3 * stretch * stretch;
}

// A mass on an undamped spring keeps its energy within 1 % over 10 s of simulated time (the
// issue's bound; velocity Verlet's error is O((omega h)^2), ~1e-5 here), and oscillates at
// omega = sqrt(k / m): after one period it is back where it started (0.5 % of the amplitude:
// the method's phase error over one period is ~1e-5).
TEST(BodySetTest, UndampedSpringKeepsItsEnergyAndPeriod) {
  BodySet set({free_body()}, glm::dvec3(0.0));
  const glm::dvec3 anchor(0.0);
  const double e0 = energy_j(set, 0, anchor);
  const double omega = std::sqrt(0.2 * 1e3 / 0.05);  // rad/s
  const int period_ticks = static_cast<int>(std::lround(2.0 * std::numbers::pi / omega / 1e-3));
  double worst = 0.0;
  for (int t = 1; t <= 10'000; ++t) {
    set.step(anchor, 1e-3);
    worst = std::max(worst, std::abs(energy_j(set, 0, anchor) - e0) / e0);
    if (t == period_ticks) {
      const double dt_off = period_ticks * 1e-3 - 2.0 * std::numbers::pi / omega;  // rounding to a tick
      EXPECT_NEAR(set.position(0).z, -35.0, 0.005 * 15.0 + 15.0 * omega * std::abs(dt_off)) << period_ticks;
    }
  }
  EXPECT_LT(worst, 0.01);
}

// Dropped onto its floor (spring negligible): the impact speed is sqrt(2 g h) (1 %: the drop
// is resolved in 0.25 ms substeps), the bounce leaves at restitution x that speed (within one
// substep of gravity, g h = 2.5 mm/s), and the impact is reported once.
TEST(BodySetTest, FloorBounceKeepsRestitutionTimesTheImpactSpeed) {
  Body b = free_body();
  b.spring_n_per_mm = 1e-9;
  b.floor = true;
  b.floor_z_mm = -100.0;
  b.radius_mm = 5.0;
  b.restitution = 0.6;
  b.position = {0, 0, -45};  // 50 mm above the floor contact height (-95)
  BodySet set({b}, glm::dvec3(0, 0, -9810));
  int impacts = 0;
  double speed = 0.0, after = 0.0;
  for (int t = 0; t < 200 && impacts == 0; ++t) {
    const BodyStepResult r = set.step(glm::dvec3(0, 0, 1000), 1e-3);
    if (r.impact_count > 0) {
      impacts += r.impact_count;
      speed = r.impacts[0].speed_mm_s;
      after = set.velocity(0).z;
    }
  }
  ASSERT_EQ(impacts, 1);
  EXPECT_NEAR(speed, std::sqrt(2.0 * 9810.0 * 50.0), 0.01 * std::sqrt(2.0 * 9810.0 * 50.0));
  EXPECT_NEAR(after, 0.6 * speed, 9810.0 * 0.25e-3 * 4);
  EXPECT_GT(after, 0.0);
}

// Through the loop: a hand sweeping at 50 mm/s through a viscous region (b = 0.01 N s/mm) in
// free space feels -b v = -0.5 N and, through the coupling (0.5 N/mm), its drawn proxy trails
// the device by b v / k = 1 mm (5 %: the Kalman velocity's ripple on a steady ramp); outside
// the region it is back on the device.
TEST(FieldLoopTest, ViscousRegionMakesTheProxyLagByBVOverK) {
  Surface floor = test::analytic(SurfaceType::kPlane);
  Scene sc = test::scene_with(8.0, {floor});
  Field v;
  v.type = FieldType::kViscous;
  v.viscosity_n_s_per_mm = 0.01;
  v.bounded = true;
  v.center = {50, 0, 30};
  v.size_mm = {60, 40, 20};
  sc.fields = {v};
  auto scene = HapticScene::build(sc);
  ASSERT_TRUE(scene);
  LogDevice device({{0.0, {0, 0, 30}, 0, true}, {2.0, {100, 0, 30}, 0, true}}, true, "sweep");
  FakeClock clock;
  HapticLoop loop(device, clock, HapticLoopParams{}, &scene.value());
  loop.run_ticks(1000);  // x = 50: mid-region, the filter settled
  HapticState st = loop.state().read();
  EXPECT_NEAR(st.position_mm.x - st.proxy_mm.x, 1.0, 0.05);
  EXPECT_NEAR(st.force_n.x, -0.5, 0.025);
  EXPECT_NEAR(st.proxy_mm.y, 0.0, 1e-9);
  loop.run_ticks(700);  // x = 85: outside
  st = loop.state().read();
  EXPECT_NEAR(st.proxy_mm.x, st.position_mm.x, 1e-9);
  EXPECT_EQ(st.force_n, glm::dvec3(0.0));
}

// A charge beside the path deflects the drawn proxy toward it (negative charge) by F / k, and the
// hand feels F (the force at the proxy, in free space), F from the softened law at the proxy.
TEST(FieldLoopTest, ChargeDeflectsTheProxyByFOverK) {
  Scene sc = test::scene_with(8.0, {test::analytic(SurfaceType::kPlane)});
  sc.fields = {charge({0, 20, 30}, -200, 2)};
  auto scene = HapticScene::build(sc);
  ASSERT_TRUE(scene);
  LogDevice device({{0.0, {0, 0, 30}, 0, true}, {1.0, {0, 0, 30}, 0, true}}, true, "hold");
  FakeClock clock;
  HapticLoop loop(device, clock, HapticLoopParams{}, &scene.value());
  loop.run_ticks(600);
  const HapticState st = loop.state().read();
  const glm::dvec3 f = FieldSet::charge_force_n(st.proxy_mm, {0, 20, 30}, -200, 2);
  // Fixed point proxy = device + F(proxy) / k: each tick re-evaluates F at the last proxy, so
  // after 600 ticks it has converged (1e-6 mm: a contraction with factor |dF/dp| / k < 0.1).
  EXPECT_GT(st.proxy_mm.y, 0.1);  // pulled toward the charge
  EXPECT_NEAR(st.proxy_mm.y, f.y / 0.5, 1e-6);
  EXPECT_NEAR(st.force_n.y, f.y, 1e-6);
}

// A body hanging from a held proxy falls, bounces on its floor and each bounce is one
// body_impact event with the reported speed; the loop publishes the body's position.
TEST(FieldLoopTest, BodyImpactsBecomeEventsAndPositionsArePublished) {
  Scene sc = test::scene_with(8.0, {test::analytic(SurfaceType::kPlane, {0, 0, -500})});
  Field g;
  g.type = FieldType::kGravity;
  sc.fields = {g};
  Body b = free_body();
  b.spring_n_per_mm = 1e-6;  // pulls with < 1e-4 N: 0.2 % of the 0.49 N weight
  b.floor = true;
  b.floor_z_mm = -60.0;
  b.position = {0, 0, -20};
  sc.bodies = {b};
  auto scene = HapticScene::build(sc);
  ASSERT_TRUE(scene);
  LogDevice device({{0.0, {0, 0, 30}, 0, true}, {3.0, {0, 0, 30}, 0, true}}, true, "hold");
  FakeClock clock;
  HapticLoop loop(device, clock, HapticLoopParams{}, &scene.value());
  std::vector<HapticEvent> impacts;
  for (int i = 0; i < 30; ++i) {
    loop.run_ticks(50);
    loop.events().drain([&](const HapticEvent& e) {
      if (e.kind == EventKind::body_impact) impacts.push_back(e);
    });
  }
  ASSERT_GE(impacts.size(), 2u);
  // First fall from 35 mm above the floor contact height (-55): sqrt(2 g h) (2 %: the weak
  // spring's pull, 0.2 % of the weight, and 0.25 ms substeps).
  EXPECT_NEAR(impacts[0].value, std::sqrt(2.0 * 9810.0 * 35.0), 0.02 * std::sqrt(2.0 * 9810.0 * 35.0));
  EXPECT_LT(impacts[1].value, impacts[0].value);  // restitution 0.6 takes energy out
  EXPECT_EQ(impacts[0].index, 0);
  const HapticState st = loop.state().read();
  EXPECT_EQ(st.body_count, 1);
  EXPECT_GE(st.body_mm[0].z, -55.0 - 1e-9);  // never below its floor
}

// Charges added and removed while the loop runs (run's C / Shift+C): the haptic thread adopts
// the published set at its next tick, raises one charge_added / charge_removed per change with
// that tick, and the probe feels the softened law of the live charge (the same closed form as
// a scene charge, checked at the converged proxy as above).
TEST(FieldLoopTest, LiveChargesAreAdoptedAtTheNextTickWithEvents) {
  Scene sc = test::scene_with(8.0, {test::analytic(SurfaceType::kPlane)});
  auto scene = HapticScene::build(sc);
  ASSERT_TRUE(scene);
  LogDevice device({{0.0, {0, 0, 30}, 0, true}, {2.0, {0, 0, 30}, 0, true}}, true, "hold");
  FakeClock clock;
  HapticLoop loop(device, clock, HapticLoopParams{}, &scene.value());
  loop.run_ticks(100);
  LiveCharges c;
  c.count = 2;
  c.id = {7, 9};
  c.position[0] = {0, 20, 30};
  c.position[1] = {0, -200, 30};
  c.charge_n_mm2[0] = -200;
  c.charge_n_mm2[1] = 50;
  loop.live_charges().publish(c);
  loop.run_ticks(1);
  std::vector<HapticEvent> events;
  loop.events().drain([&](const HapticEvent& e) { events.push_back(e); });
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[0].kind, EventKind::charge_added);
  EXPECT_EQ(events[0].index, 7);
  EXPECT_EQ(events[0].tick, 100u);
  EXPECT_EQ(events[1].index, 9);
  loop.run_ticks(600);
  const HapticState st = loop.state().read();
  const glm::dvec3 f = FieldSet::charge_force_n(st.proxy_mm, c.position[0], -200, 2) +
                       FieldSet::charge_force_n(st.proxy_mm, c.position[1], 50, 2);
  EXPECT_NEAR(st.force_n.y, f.y, 1e-6);
  EXPECT_GT(st.proxy_mm.y, 0.1);
  c.count = 1;  // the first one removed: id 9 moves to slot 0
  c.id[0] = 9;
  c.position[0] = c.position[1];
  c.charge_n_mm2[0] = 50;
  loop.live_charges().publish(c);
  loop.run_ticks(1);
  events.clear();
  loop.events().drain([&](const HapticEvent& e) { events.push_back(e); });
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, EventKind::charge_removed);
  EXPECT_EQ(events[0].index, 7);
  EXPECT_EQ(events[0].value, -200.0);
}

// No fields, no bodies: the field force is exactly zero and the proxy is today's.
TEST(FieldLoopTest, PlainSceneHasNoFieldForce) {
  Scene sc = test::scene_with(8.0, {test::analytic(SurfaceType::kPlane)});
  auto scene = HapticScene::build(sc);
  ASSERT_TRUE(scene);
  EXPECT_TRUE(scene->fields().empty());
  LogDevice device({{0.0, {0, 0, 30}, 0, true}, {1.0, {40, 0, 4}, 0, true}}, true, "press");
  FakeClock clock;
  HapticLoop loop(device, clock, HapticLoopParams{}, &scene.value());
  loop.run_ticks(900);
  EXPECT_EQ(loop.state().read().field_force_n, glm::dvec3(0.0));
  EXPECT_EQ(loop.state().read().body_count, 0);
}

}  // namespace
}  // namespace ps::world
