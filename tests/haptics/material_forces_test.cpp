// Material force laws (src/haptics/material_forces.h) against their closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "haptics/force_model.h"
#include "haptics/material_forces.h"

namespace ps {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Closed forms evaluated in double by a different route than the code (a pow vs a product, a
// sin at an exact quarter period): agreement to a few ulps of ~1 N values.
constexpr double kTol = 1e-12;

const glm::dvec3 kUp{0.0, 0.0, 1.0};

MaterialContact contact(double distance_mm, glm::dvec3 velocity = glm::dvec3(0.0)) {
  MaterialContact c;
  c.distance_mm = distance_mm;
  c.velocity_mm_s = velocity;
  return c;
}

TEST(MaterialForcesTest, DefaultsAreTheFormerGlobalHapticsParams) {
  const HapticMaterial m;
  const HapticsParams p;
  EXPECT_EQ(m.stiffness_n_per_mm, p.stiffness_n_per_mm);
  EXPECT_EQ(m.stiffness_exponent, p.stiffness_exponent);
  EXPECT_EQ(m.damping_n_s_per_mm, p.damping_n_s_per_mm);
  EXPECT_EQ(m.viscosity_n_s_per_mm, p.viscosity_n_s_per_mm);
  EXPECT_EQ(m.static_friction, p.static_friction);
  EXPECT_EQ(m.dynamic_friction, p.dynamic_friction);
}

TEST(MaterialForcesTest, SpringIsAlphaRToTheOnePlusBeta) {
  HapticMaterial m;
  m.stiffness_n_per_mm = 0.5;
  m.stiffness_exponent = 0.5;
  EXPECT_NEAR(spring_force_magnitude_n(m, 4.0), 0.5 * 4.0 * 2.0, kTol);  // 0.5 * 4^1.5
  EXPECT_EQ(spring_force_magnitude_n(m, 0.0), 0.0);
  EXPECT_EQ(spring_force_magnitude_n(m, -1.0), 0.0) << "no contact, no spring";
  m.penetrable = true;
  EXPECT_EQ(spring_force_magnitude_n(m, 4.0), 0.0) << "a fluid has no surface spring";
  const MaterialForces f = material_forces(HapticMaterial{}, contact(-2.0), FrictionHistory{});
  EXPECT_NEAR(f.spring_n.z, 0.5 * 2.0, kTol);  // default: linear, 0.5 N/mm
}

TEST(MaterialForcesTest, DampingActsOnTheNormalVelocityInContactOnly) {
  HapticMaterial m;
  m.damping_n_s_per_mm = 0.002;
  const glm::dvec3 v{10.0, 0.0, -100.0};
  EXPECT_NEAR(damping_force_n(m, contact(-1.0, v)).z, 0.2, kTol);  // -0.002 * -100
  EXPECT_EQ(damping_force_n(m, contact(-1.0, v)).x, 0.0) << "tangential velocity: no damping";
  EXPECT_EQ(damping_force_n(m, contact(1.0, v)), glm::dvec3(0.0));
}

TEST(MaterialForcesTest, ViscosityIsMinusBVInsideAPenetrableMaterialOnly) {
  HapticMaterial m;
  m.penetrable = true;
  m.viscosity_n_s_per_mm = 0.02;
  const glm::dvec3 v{100.0, 0.0, -50.0};
  const MaterialForces inside = material_forces(m, contact(-5.0, v), FrictionHistory{});
  EXPECT_NEAR(inside.viscosity_n.x, -2.0, kTol);
  EXPECT_NEAR(inside.viscosity_n.z, 1.0, kTol);
  EXPECT_EQ(inside.total(), inside.viscosity_n) << "inside a fluid only the viscosity acts";
  EXPECT_EQ(viscosity_force_n(m, contact(2.0, v)), glm::dvec3(0.0)) << "outside";
  m.penetrable = false;
  EXPECT_EQ(viscosity_force_n(m, contact(-5.0, v)), glm::dvec3(0.0));
}

TEST(MaterialForcesTest, FrictionCoefficientRampsToTheStaticPeakThenSlides) {
  HapticMaterial m;
  m.static_friction = 0.6;
  m.dynamic_friction = 0.4;
  m.stick_speed_mm_s = 2.0;
  EXPECT_EQ(friction_coefficient(m, 0.0), 0.0);
  EXPECT_NEAR(friction_coefficient(m, 1.0), 0.3, kTol);
  EXPECT_NEAR(friction_coefficient(m, 1.999999), 0.6, 1e-6);  // the peak, just below v0
  EXPECT_EQ(friction_coefficient(m, 2.0), 0.4);
  EXPECT_EQ(friction_coefficient(m, 500.0), 0.4);
}

TEST(MaterialForcesTest, FrictionStaysInsideTheConeAndOpposesTheMotion) {
  HapticMaterial m;
  m.static_friction = 0.6;
  m.dynamic_friction = 0.4;
  for (double speed : {0.0, 0.5, 1.9, 2.0, 10.0, 300.0}) {
    FrictionHistory h;
    for (int i = 0; i <= 10; ++i) h.push({i * speed * 1e-3, 0.0, 0.0});  // 1 kHz ticks
    const MaterialContact c = contact(-1.0, {speed, 0.0, 0.0});
    const glm::dvec3 f = friction_force_n(m, c, 2.0, h);
    EXPECT_LE(glm::length(f), m.static_friction * 2.0 + kTol) << speed;
    EXPECT_LE(f.x, 0.0) << speed;
    EXPECT_EQ(f.z, 0.0) << "tangential only";
    EXPECT_NEAR(-f.x, friction_coefficient(m, speed) * 2.0, kTol) << speed;
  }
  m.penetrable = true;
  FrictionHistory h;
  EXPECT_EQ(friction_force_n(m, contact(-1.0, {50, 0, 0}), 2.0, h), glm::dvec3(0.0));
}

TEST(MaterialForcesTest, FrictionDirectionIsAveragedOverTheHistory) {
  HapticMaterial m;
  m.friction_history_ticks = 8;
  FrictionHistory h;
  // Zig-zag jitter across y on a steady drift along x: the mean of 8 steps (an even number of
  // +-y) cancels y exactly, so the friction points straight along -x though no single step does.
  glm::dvec3 p(0.0);
  h.push(p);
  for (int i = 0; i < 40; ++i) {
    p += glm::dvec3(0.1, (i % 2 == 0) ? 0.5 : -0.5, 0.0);
    h.push(p);
  }
  const glm::dvec3 d = h.direction(m.friction_history_ticks, kUp);
  EXPECT_NEAR(d.x, 1.0, kTol);
  EXPECT_NEAR(d.y, 0.0, kTol);
  // The velocity, even pointing elsewhere, sets only the speed; the history sets the direction.
  const glm::dvec3 f = friction_force_n(m, contact(-1.0, {0.0, 100.0, 0.0}), 1.0, h);
  EXPECT_NEAR(f.x, -m.dynamic_friction, kTol);
  EXPECT_NEAR(f.y, 0.0, kTol);
}

TEST(MaterialForcesTest, HistoryIsARingOfTheNewestSteps) {
  FrictionHistory h;
  h.push({0, 0, 0});
  for (int i = 1; i <= 50; ++i) h.push({0.0, double(i), 0.0});  // 50 steps along +y
  for (int i = 1; i <= 5; ++i) h.push({double(i), 50.0, 0.0});  // then 5 along +x
  EXPECT_EQ(h.steps(), kMaxFrictionHistoryTicks);
  EXPECT_EQ(h.direction(5, kUp), glm::dvec3(1.0, 0.0, 0.0));
  const glm::dvec3 d6 = h.direction(6, kUp);  // 5 along x, 1 along y
  EXPECT_NEAR(d6.x, 5.0 / std::sqrt(26.0), kTol);
  EXPECT_NEAR(d6.y, 1.0 / std::sqrt(26.0), kTol);
  // A step along the normal is not a direction of sliding.
  FrictionHistory n;
  n.push({0, 0, 0});
  n.push({0, 0, 3});
  EXPECT_EQ(n.direction(8, kUp), glm::dvec3(0.0));
  h.reset();
  EXPECT_EQ(h.steps(), 0);
}

TEST(MaterialForcesTest, MagneticPullIsZeroAtContactPeaksAtHalfRangeAndEndsAtRange) {
  HapticMaterial m;
  m.magnetic_force_n = 1.5;
  m.magnetic_range_mm = 10.0;
  EXPECT_EQ(magnetic_force_magnitude_n(m, 0.0), 0.0);
  EXPECT_EQ(magnetic_force_magnitude_n(m, -1.0), 0.0) << "inside: the spring's business";
  EXPECT_EQ(magnetic_force_magnitude_n(m, 10.0), 0.0);
  EXPECT_EQ(magnetic_force_magnitude_n(m, 25.0), 0.0);
  EXPECT_NEAR(magnetic_force_magnitude_n(m, 5.0), 1.5, kTol);
  EXPECT_NEAR(magnetic_force_magnitude_n(m, 2.5), 1.5 * 16.0 * (0.25 * 0.25) * (0.75 * 0.75), kTol);
  // Falls to zero at contact quadratically: at 1 um it is 16 (1e-4)^2 of the peak.
  EXPECT_LT(magnetic_force_magnitude_n(m, 1e-3), 1.5 * 16.0 * 1e-8 * 1.0001);
  double last = 0.0;
  for (double d = 0.05; d <= 5.0; d += 0.05) {
    const double f = magnetic_force_magnitude_n(m, d);
    EXPECT_GT(f, last) << "rises monotonically toward the peak at " << d;
    last = f;
  }
  const glm::dvec3 pull = magnetic_force_n(m, contact(5.0));
  EXPECT_NEAR(pull.z, -1.5, kTol) << "toward the surface";
}

TEST(MaterialForcesTest, StickinessResistsLeavingOnly) {
  HapticMaterial m;
  m.stickiness_n = 1.5;
  m.stick_speed_mm_s = 2.0;
  EXPECT_NEAR(stickiness_force_n(m, contact(-0.5, {0, 0, 10.0})).z, -1.5, kTol);
  EXPECT_NEAR(stickiness_force_n(m, contact(-0.5, {0, 0, 1.0})).z, -0.75, kTol);
  EXPECT_EQ(stickiness_force_n(m, contact(-0.5, {0, 0, -10.0})), glm::dvec3(0.0)) << "pressing";
  EXPECT_EQ(stickiness_force_n(m, contact(-0.5, {10.0, 0, 0})), glm::dvec3(0.0)) << "sliding";
  EXPECT_EQ(stickiness_force_n(m, contact(0.5, {0, 0, 10.0})), glm::dvec3(0.0)) << "released";
}

TEST(MaterialForcesTest, TextureIsTheSumOfItsWavesAlongTheSurface) {
  HapticMaterial m;
  m.texture.push_back({HapticWave::Shape::kSine, 0.2, 4.0, {1.0, 0.0}});
  EXPECT_NEAR(texture_value_n(m, {1.0, 7.0}), 0.2, kTol);   // quarter period; y ignored
  EXPECT_NEAR(texture_value_n(m, {3.0, -2.0}), -0.2, kTol);
  EXPECT_NEAR(texture_value_n(m, {0.5, 0.0}), 0.2 * std::sin(kPi / 4.0), kTol);
  m.texture.push_back({HapticWave::Shape::kSquare, 0.1, 2.0, {0.0, 1.0}});
  EXPECT_NEAR(texture_value_n(m, {1.0, 0.25}), 0.2 + 0.1, kTol);
  EXPECT_NEAR(texture_value_n(m, {1.0, 1.25}), 0.2 - 0.1, kTol);
  const MaterialContact c = [] {
    MaterialContact c = contact(-2.0);
    c.surface_mm = {1.0, 0.25};
    return c;
  }();
  EXPECT_NEAR(texture_force_n(m, c).z, 0.3, kTol) << "along the normal";
  EXPECT_EQ(texture_force_n(m, contact(1.0)), glm::dvec3(0.0)) << "felt only in contact";
}

TEST(MaterialForcesTest, RestitutionScalesTheApproachingNormalVelocity) {
  HapticMaterial m;
  m.restitution = 0.5;
  const glm::dvec3 out = restitution_velocity_mm_s(m, kUp, {3.0, 0.0, -10.0});
  EXPECT_EQ(out, glm::dvec3(3.0, 0.0, 5.0));
  EXPECT_EQ(restitution_velocity_mm_s(m, kUp, {3.0, 0.0, 10.0}), glm::dvec3(3.0, 0.0, 10.0))
      << "already leaving: unchanged";
  m.restitution = 1.0;
  EXPECT_EQ(glm::length(restitution_velocity_mm_s(m, kUp, {3.0, 4.0, -12.0})), 13.0)
      << "elastic: speed kept";
  m.restitution = 0.0;
  EXPECT_EQ(restitution_velocity_mm_s(m, kUp, {3.0, 0.0, -10.0}), glm::dvec3(3.0, 0.0, 0.0));
}

TEST(MaterialForcesTest, ASurfacePushesButNeverPulls) {
  HapticMaterial m;  // 0.5 N/mm, K_d 0.002 N s/mm
  m.texture.push_back({HapticWave::Shape::kSine, 5.0, 4.0, {1.0, 0.0}});
  MaterialContact c = contact(-1.0, {0.0, 0.0, 1000.0});  // leaving fast: damping -2 N
  c.surface_mm = {3.0, 0.0};                                // texture at its -5 N trough
  const MaterialForces f = material_forces(m, c, FrictionHistory{});
  EXPECT_NEAR(f.spring_n.z, 0.5, kTol);
  EXPECT_NEAR(f.damping_n.z, -0.5, kTol) << "cut to the spring";
  EXPECT_NEAR(f.texture_n.z, 0.0, kTol) << "nothing left to cut";
  EXPECT_NEAR(f.total().z, 0.0, kTol);
  EXPECT_EQ(f.friction_n, glm::dvec3(0.0)) << "no normal push, no friction";
}

}  // namespace
}  // namespace ps
