// The material laws in the god-object force (compute_proxy_force): magnetic pull near a
// magnetic box and sphere, texture along a plane, stickiness, viscosity inside water volumes,
// and a plain scene whose forces are those of the formula the loop used before materials were
// wired in. Expected values are written out here from the laws in docs/haptics.md, not taken
// from material_forces.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "haptics/force_model.h"
#include "world/god_object.h"
#include "world_test_util.h"

namespace ps::world {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kProbeMm = 5.0;

// One material per surface, in order; surfaces get material_index = their position.
Scene scene_of(std::initializer_list<std::pair<Surface, HapticMaterial>> parts) {
  Scene sc = test::scene_with(kProbeMm, {});
  sc.materials.clear();
  for (const auto& [surface, feel] : parts) {
    Material m;
    m.name = "m" + std::to_string(sc.materials.size());
    m.haptic = feel;
    Surface s = surface;
    s.material_index = static_cast<int>(sc.materials.size());
    sc.materials.push_back(m);
    sc.surfaces.push_back(s);
  }
  return sc;
}

HapticMaterial frictionless() {
  HapticMaterial m;
  m.static_friction = m.dynamic_friction = 0.0;
  return m;
}

HapticMaterial magnet(double force_n, double range_mm) {
  HapticMaterial m = frictionless();
  m.magnetic_force_n = force_n;
  m.magnetic_range_mm = range_mm;
  return m;
}

// The device held still at x: the force of one tick from a proxy placed there.
ForceResult held_at(const HapticScene& scene, const glm::dvec3& x, const glm::dvec3& v = glm::dvec3(0.0)) {
  GodObject god(scene);
  god.reset(x);
  return compute_proxy_force(HapticsParams{}, god, x, v, 0.0);
}

// A Virtual Universe §3 as docs/haptics.md writes it: F_m 16 s^2 (1 - s)^2, s = gap / range,
// inside (0, range).
double magnetic_pull(double force_n, double range_mm, double gap_mm) {
  if (gap_mm <= 0.0 || gap_mm >= range_mm) return 0.0;
  const double s = gap_mm / range_mm;
  return force_n * 16.0 * s * s * (1.0 - s) * (1.0 - s);
}

// The force is a handful of double products and sums of O(1) N values: 1e-12 N is far above
// their rounding and far below any force a device renders.
constexpr double kForceTolN = 1e-12;

TEST(MaterialWiringTest, MagneticBoxPullsWithTheClosedFormWithinRangeAndNotBeyond) {
  Surface box = test::analytic(SurfaceType::kBox, {0.0, 0.0, -20.0});
  box.box_size_mm = {60.0, 50.0, 40.0};  // top face at z = 0
  auto scene = HapticScene::build(scene_of({{box, magnet(2.0, 10.0)}}));
  ASSERT_TRUE(scene) << scene.error().message;
  EXPECT_EQ(scene->max_magnetic_range_mm(), 10.0);
  for (double gap : {0.5, 2.5, 5.0, 7.5, 9.5, 10.0, 10.5, 20.0}) {
    const ForceResult f = held_at(*scene, {3.0, -4.0, kProbeMm + gap});
    EXPECT_FALSE(f.in_contact) << gap;
    EXPECT_NEAR(f.force_n.z, -magnetic_pull(2.0, 10.0, gap), kForceTolN) << "gap " << gap;
    EXPECT_NEAR(f.force_n.x, 0.0, kForceTolN);
    EXPECT_NEAR(f.force_n.y, 0.0, kForceTolN);
  }
  // Strongest at half the range (F_m), a check on the expected values themselves.
  EXPECT_NEAR(held_at(*scene, {0.0, 0.0, kProbeMm + 5.0}).force_n.z, -2.0, kForceTolN);
}

TEST(MaterialWiringTest, MagneticSpherePullsTowardItsCentre) {
  Surface ball = test::analytic(SurfaceType::kSphere, {10.0, 0.0, 0.0});
  ball.radius_mm = 20.0;
  auto scene = HapticScene::build(scene_of({{ball, magnet(1.5, 8.0)}}));
  ASSERT_TRUE(scene);
  const glm::dvec3 dir = glm::normalize(glm::dvec3(1.0, 2.0, -2.0));
  for (double gap : {1.0, 3.0, 6.0, 8.5}) {
    const ForceResult f = held_at(*scene, ball.center + (20.0 + kProbeMm + gap) * dir);
    const glm::dvec3 expected = -magnetic_pull(1.5, 8.0, gap) * dir;
    EXPECT_NEAR(glm::length(f.force_n - expected), 0.0, kForceTolN) << "gap " << gap;
  }
  EXPECT_GT(glm::length(held_at(*scene, ball.center + 28.0 * dir).force_n), 0.1);  // gap 3: it pulls
}

TEST(MaterialWiringTest, NoMagneticMaterialMeansNoMagneticReach) {
  Surface box = test::analytic(SurfaceType::kBox);
  HapticMaterial water = frictionless();
  water.penetrable = true;
  water.magnetic_force_n = 3.0;  // penetrable: no surface to be pulled to
  water.magnetic_range_mm = 10.0;
  auto scene = HapticScene::build(scene_of({{box, frictionless()}, {box, water}}));
  ASSERT_TRUE(scene);
  EXPECT_EQ(scene->max_magnetic_range_mm(), 0.0);
}

TEST(MaterialWiringTest, NormalForceFollowsTheTextureAlongAPlane) {
  HapticMaterial rough = frictionless();
  rough.texture.push_back({HapticWave::Shape::kSine, 0.3, 4.0, {1.0, 0.0}});
  auto scene = HapticScene::build(scene_of({{test::analytic(SurfaceType::kPlane), rough}}));
  ASSERT_TRUE(scene);
  GodObject god(*scene);
  const double depth = 2.0;
  god.reset({-9.0, 0.0, 20.0});
  compute_proxy_force(HapticsParams{}, god, {-9.0, 0.0, kProbeMm - depth}, glm::dvec3(0.0), 0.0);
  std::vector<double> crossings;  // x where the texture part of F_z changes sign
  double last = 0.0;
  const double step = 0.01;  // mm per tick: 10 mm/s at 1 kHz
  for (double x = -9.0; x <= 9.0; x += step) {
    const ForceResult f = compute_proxy_force(HapticsParams{}, god, {x, 0.0, kProbeMm - depth}, {10.0, 0.0, 0.0}, 0.0);
    ASSERT_TRUE(f.in_contact) << x;
    const double texture = f.force_n.z - rough.stiffness_n_per_mm * f.penetration_mm;
    EXPECT_NEAR(texture, 0.3 * std::sin(2.0 * kPi * f.proxy_mm.x / 4.0), 1e-9) << "x " << x;
    if (last != 0.0 && (texture > 0.0) != (last > 0.0)) crossings.push_back(x);
    last = texture;
  }
  // Zeros of sin(2 pi x / 4) in (-9, 9): -8, -6, ..., 8.
  ASSERT_EQ(crossings.size(), 9u);
  const double period = 2.0 * (crossings.back() - crossings.front()) / (crossings.size() - 1);
  EXPECT_NEAR(period, 4.0, 2.0 * step);  // each crossing is seen up to one tick late
}

TEST(MaterialWiringTest, StickinessResistsPullingAway) {
  HapticMaterial sticky = frictionless();
  sticky.stickiness_n = 0.8;
  sticky.damping_n_s_per_mm = 0.0;
  auto scene = HapticScene::build(scene_of({{test::analytic(SurfaceType::kPlane), sticky}}));
  ASSERT_TRUE(scene);
  GodObject god(*scene);
  god.reset({0.0, 0.0, 20.0});
  const glm::dvec3 x{0.0, 0.0, kProbeMm - 1.0};
  compute_proxy_force(HapticsParams{}, god, x, glm::dvec3(0.0), 0.0);
  // Outward at half the stick speed (2 mm/s): half the stickiness pulls back in.
  const ForceResult out = compute_proxy_force(HapticsParams{}, god, x, {0.0, 0.0, 1.0}, 0.0);
  EXPECT_NEAR(out.force_n.z, 0.5 * out.penetration_mm - 0.4, kForceTolN);
  // Inward: stickiness does nothing.
  const ForceResult in = compute_proxy_force(HapticsParams{}, god, x, {0.0, 0.0, -1.0}, 0.0);
  EXPECT_NEAR(in.force_n.z, 0.5 * in.penetration_mm, kForceTolN);
}

TEST(MaterialWiringTest, InsideAWaterSphereOrBoxTheForceIsMinusBV) {
  HapticMaterial water = frictionless();
  water.penetrable = true;
  water.viscosity_n_s_per_mm = 0.01;
  Surface ball = test::analytic(SurfaceType::kSphere, {0.0, 0.0, 0.0});
  ball.radius_mm = 20.0;
  Surface tank = test::analytic(SurfaceType::kBox, {100.0, 0.0, 0.0}, {0.0, 0.0, 45.0});
  tank.box_size_mm = {40.0, 20.0, 10.0};
  auto scene = HapticScene::build(scene_of({{ball, water}, {tank, water}}));
  ASSERT_TRUE(scene);
  const glm::dvec3 v{30.0, -10.0, 5.0};
  struct Case { glm::dvec3 x; int medium; };
  const double diag = 0.5 * std::sqrt(2.0);  // the tank's local X is the world's (1, 1, 0)/sqrt 2
  for (const Case& c : {Case{{0.0, 0.0, 0.0}, 0}, Case{{0.0, 19.5, 0.0}, 0}, Case{{0.0, 20.5, 0.0}, -1},
                        Case{{14.0, 13.0, 3.0}, 0}, Case{{100.0 + 19.5 * diag, 19.5 * diag, 4.5}, 1},
                        Case{{100.0 + 19.5 * diag, 19.5 * diag, 5.5}, -1},
                        Case{{100.0 + 10.5 * diag, -10.5 * diag, 0.0}, -1}}) {
    const ForceResult f = held_at(*scene, c.x, v);
    EXPECT_EQ(f.medium, c.medium) << c.x.x << "," << c.x.y << "," << c.x.z;
    EXPECT_FALSE(f.in_contact);  // the proxy passes through water
    EXPECT_EQ(f.proxy_mm, c.x);
    const glm::dvec3 expected = c.medium >= 0 ? -0.01 * v : glm::dvec3(0.0);
    EXPECT_NEAR(glm::length(f.force_n - expected), 0.0, kForceTolN);
  }
}

TEST(MaterialWiringTest, InsideAWaterTorusTube) {
  HapticMaterial water = frictionless();
  water.penetrable = true;
  water.viscosity_n_s_per_mm = 0.02;
  Surface ring = test::analytic(SurfaceType::kTorus, {0.0, 0.0, 0.0}, {90.0, 0.0, 0.0});  // ring in XZ
  ring.radius_mm = 40.0;
  ring.minor_radius_mm = 10.0;
  auto scene = HapticScene::build(scene_of({{ring, water}}));
  ASSERT_TRUE(scene);
  EXPECT_EQ(scene->medium_at({0.0, 0.0, 45.0}), 0);   // in the tube
  EXPECT_EQ(scene->medium_at({0.0, 0.0, 0.0}), -1);   // the hole
  EXPECT_EQ(scene->medium_at({0.0, 45.0, 0.0}), -1);  // where the ring would be unrotated
  EXPECT_EQ(scene->medium_at({0.0, 9.0, 40.0}), 0);
  EXPECT_EQ(scene->medium_at({0.0, 11.0, 40.0}), -1);
}

// --- plain scene: the force before materials were wired in -------------------------------

// compute_proxy_force as it was: spring and damping along n, the stick/slide cone with the
// spring as normal force, nothing else. Kept verbatim as the reference.
glm::dvec3 reference_friction(const HapticsParams& p, const glm::dvec3& n, double normal_n,
                              const glm::dvec3& x_surface, glm::dvec3& proxy) {
  const glm::dvec3 offset = (glm::dmat3(1.0) - glm::outerProduct(n, n)) * (proxy - x_surface);
  const double len = glm::length(offset);
  const double k = p.tangent_stiffness_n_per_mm;
  if (k <= 0.0 || len <= 0.0) { proxy = x_surface; return glm::dvec3(0.0); }
  if (k * len <= p.static_friction * normal_n) { proxy = x_surface + offset; return k * offset; }
  const double slide_n = p.dynamic_friction * normal_n;
  proxy = x_surface + offset * (slide_n / (k * len));
  return offset * (slide_n / len);
}

ForceResult reference_force(const HapticsParams& p, GodObject& god, const glm::dvec3& x, const glm::dvec3& v) {
  ForceResult out;
  glm::dvec3 f = -p.viscosity_n_s_per_mm * v;
  const glm::dvec3 stick_point = god.proxy();
  const ProxyStep step = god.move(x);
  out.proxy_mm = step.proxy_mm;
  const double r = glm::length(step.proxy_mm - x);
  if (step.in_contact && r > 0.0) {
    const HapticsParams q = with_material(p, god.scene().material(step.surface));
    out.in_contact = true;
    const glm::dvec3 n = q.force_shading ? step.shaded_normal : (step.proxy_mm - x) / r;
    const double fn = q.stiffness_n_per_mm * std::pow(r, 1.0 + q.stiffness_exponent);
    f += fn * n;
    f -= q.damping_n_s_per_mm * glm::dot(n, v) * n;
    glm::dvec3 held = stick_point;
    f += reference_friction(q, step.contact_normal, fn, step.proxy_mm, held);
    if (held != step.proxy_mm) out.proxy_mm = god.move(held).proxy_mm;
  }
  const double len = glm::length(f);
  if (len > p.max_force_n && len > 0.0) f *= p.max_force_n / len;
  out.force_n = f;
  return out;
}

TEST(MaterialWiringTest, PlainSceneFeelsAsBefore) {
  Surface ball = test::analytic(SurfaceType::kSphere, {0.0, 0.0, 0.0});
  ball.radius_mm = 20.0;
  Surface box = test::analytic(SurfaceType::kBox, {0.0, 0.0, -30.0}, {0.0, 10.0, 20.0});
  box.box_size_mm = {120.0, 120.0, 20.0};
  // Default materials: friction, damping, no texture, stickiness, magnetism or medium.
  auto scene = HapticScene::build(scene_of({{ball, HapticMaterial{}}, {box, HapticMaterial{}}}));
  ASSERT_TRUE(scene);
  EXPECT_EQ(scene->max_magnetic_range_mm(), 0.0);
  GodObject now(*scene), before(*scene);
  glm::dvec3 x{0.0, 0.0, 40.0}, last = x;
  now.reset(x);
  before.reset(x);
  int contacts = 0, sticking = 0;
  for (int i = 0; i < 3000; ++i) {  // down onto the sphere, round it, down the side onto the box
    const double t = i * 1e-3;
    x = {12.0 * std::sin(2.0 * t), 10.0 * std::sin(1.3 * t), 40.0 - 20.0 * t};
    const glm::dvec3 v = (x - last) / 1e-3;
    last = x;
    const ForceResult a = compute_proxy_force(HapticsParams{}, now, x, v, t);
    const ForceResult b = reference_force(HapticsParams{}, before, x, v);
    ASSERT_NEAR(glm::length(a.force_n - b.force_n), 0.0, kForceTolN) << "tick " << i;
    ASSERT_EQ(a.proxy_mm, b.proxy_mm) << "tick " << i;
    ASSERT_EQ(a.medium, -1);
    contacts += a.in_contact;
    sticking += a.sticking;
  }
  EXPECT_GT(contacts, 1000);  // the path was in contact most of the way, friction included
  EXPECT_GT(sticking, 0);
}

}  // namespace
}  // namespace ps::world
