// Force models against their closed forms (docs/haptics.md).
#include <gtest/gtest.h>

#include <cmath>

#include "floor_model.h"
#include "haptics/force_model.h"

namespace ps {
namespace {

HapticsParams bare() {  // every effect off; tests switch on the one they check
  HapticsParams p;
  p.damping_n_s_per_mm = 0.0;
  p.static_friction = p.dynamic_friction = 0.0;
  p.tangent_stiffness_n_per_mm = 0.0;
  p.max_force_n = 1e9;
  return p;
}

using test::floor_model;  // plane z = 0, probe radius 8 mm

TEST(ForceModelTest, ProjectorsDecomposeOrthogonally) {
  const glm::dvec3 n = glm::normalize(glm::dvec3(0.3, -0.5, 0.8));
  const glm::dmat3 P = normal_projector(n), Q = tangent_projector(n), sum = P + Q, prod = P * Q;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(sum[i][j], i == j ? 1.0 : 0.0, 1e-15);
      EXPECT_NEAR(prod[i][j], 0.0, 1e-15);
    }
  const glm::dvec3 v(1.0, 2.0, 3.0);
  EXPECT_NEAR(glm::dot(P * v, Q * v), 0.0, 1e-14);
}

TEST(ForceModelTest, SpringIsAlphaRPowOnePlusBeta) {
  HapticsParams p = bare();
  p.stiffness_n_per_mm = 0.4;
  const SurfaceModel m = floor_model();
  for (double beta : {0.0, 0.5, 1.0}) {
    p.stiffness_exponent = beta;
    const ForceResult f = compute_force(p, m, {0, 0, 5.0}, glm::dvec3(0.0), {0, 0, 5.0}, 0.0);  // r = 3 mm
    EXPECT_TRUE(f.in_contact);
    EXPECT_DOUBLE_EQ(f.penetration_mm, 3.0);
    EXPECT_NEAR(f.force_n.z, 0.4 * std::pow(3.0, 1.0 + beta), 1e-12);
    EXPECT_NEAR(f.force_n.x, 0.0, 1e-15);
    EXPECT_NEAR(f.proxy_mm.z, 8.0, 1e-12);  // proxy on the surface
  }
  const ForceResult free = compute_force(p, m, {0, 0, 9.0}, glm::dvec3(0.0), {0, 0, 9.0}, 0.0);
  EXPECT_FALSE(free.in_contact);
  EXPECT_EQ(free.force_n, glm::dvec3(0.0));
}

TEST(ForceModelTest, DampingActsOnNormalVelocityOnly) {
  HapticsParams p = bare();
  p.stiffness_n_per_mm = 0.0;
  p.damping_n_s_per_mm = 0.002;
  const ForceResult f = compute_force(p, floor_model(), {0, 0, 7.0}, {50.0, 0.0, -100.0}, {0, 0, 8}, 0.0);
  EXPECT_NEAR(f.force_n.z, 0.2, 1e-12);   // -K_d (n.v) n
  EXPECT_NEAR(f.force_n.x, 0.0, 1e-15);
}

TEST(ForceModelTest, ViscosityIsMinusBV) {
  HapticsParams p = bare();
  p.viscosity_n_s_per_mm = 0.01;
  const glm::dvec3 v(30.0, -20.0, 5.0);
  const ForceResult f = compute_force(p, SurfaceModel{}, {0, 0, 50}, v, {0, 0, 50}, 0.0);
  EXPECT_NEAR(glm::length(f.force_n + 0.01 * v), 0.0, 1e-14);
}

TEST(ForceModelTest, FrictionConeSticksThenSlidesAtDynamicCoefficient) {
  HapticsParams p = bare();
  p.stiffness_n_per_mm = 1.0;
  p.static_friction = 0.5;
  p.dynamic_friction = 0.3;
  p.tangent_stiffness_n_per_mm = 1.0;
  const SurfaceModel m = floor_model();
  // r = 2 mm -> |f_n| = 2 N; static limit 1 N = 1 mm of tangent offset.
  const glm::dvec3 proxy(0, 0, 8);
  const ForceResult stick = compute_force(p, m, {0.8, 0, 6}, glm::dvec3(0.0), proxy, 0.0);
  EXPECT_TRUE(stick.sticking);
  EXPECT_NEAR(stick.force_n.x, -0.8, 1e-12);  // k_t * Q(proxy - x)
  EXPECT_NEAR(stick.proxy_mm.x, 0.0, 1e-12);
  const ForceResult slide = compute_force(p, m, {3.0, 0, 6}, glm::dvec3(0.0), proxy, 0.0);
  EXPECT_FALSE(slide.sticking);
  EXPECT_NEAR(slide.force_n.x, -0.3 * 2.0, 1e-12);  // mu_d |f_n|
  EXPECT_NEAR(slide.force_n.z, 2.0, 1e-12);
  EXPECT_NEAR(slide.proxy_mm.x, 3.0 - 0.6, 1e-12);   // proxy dragged to the cone boundary
  // The tangent force never leaves the static cone.
  EXPECT_LE(std::hypot(slide.force_n.x, slide.force_n.y), 0.5 * slide.force_n.z + 1e-12);
}

TEST(ForceModelTest, ExternalForceConstantPlusFluctuation) {
  HapticsParams p = bare();
  p.external_force_n = {0, 1.0, 0};
  p.external_fluctuation_n = {0, 0.5, 0};
  p.external_frequency_hz = 2.0;
  EXPECT_NEAR(external_force_n(p, 0.125).y, 1.5, 1e-12);  // sin(pi/2)
  EXPECT_NEAR(external_force_n(p, 0.375).y, 0.5, 1e-12);
}

TEST(ForceModelTest, ForceIsClampedToMaximum) {
  HapticsParams p = bare();
  p.stiffness_n_per_mm = 10.0;
  p.max_force_n = 3.0;
  const ForceResult f = compute_force(p, floor_model(), {0, 0, 0}, glm::dvec3(0.0), {0, 0, 8}, 0.0);
  EXPECT_NEAR(glm::length(f.force_n), 3.0, 1e-12);
}

TEST(ForceModelTest, SurfaceModelFromFrame) {
  SurfaceModel m;
  // Probe centre at z = 7 with radius 8 penetrating 1 mm: surface at z = 0.
  m = update_surface_model(m, {0, 0, 2}, {5, 5, 7}, 8.0, 1.0, true, 1);
  EXPECT_TRUE(m.valid);
  EXPECT_NEAR(m.point_mm.z, 0.0, 1e-12);
  m = update_surface_model(m, {0, 0, 1}, {5, 5, 20}, 8.0, 0.0, true, 2);  // no contact: kept
  EXPECT_TRUE(m.valid);
  m = update_surface_model(m, {0, 0, 1}, {5, 5, 90}, 8.0, 0.0, false, 3);  // no shadow: dropped
  EXPECT_FALSE(m.valid);
}

}  // namespace
}  // namespace ps
