// The 4D haptic rolling manifold (Hanson & Zhang §6, src/fourd/rolling.h, docs/fourd.md "Rolling
// manifold"): Hanson & Zhang's Rotate(theta, N), the rubber-band tether (eq. 1, beta = 3), one step
// across a facet edge, and the haptic loop walking over the flat torus with the view rolling.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>

#include "devices/sample_log.h"
#include "fourd/rolling.h"
#include "haptics/haptic_loop.h"
#include "scene/scene_io.h"
#include "world/haptic_scene.h"

namespace ps {
namespace {

using fourd::RollContact;
using fourd::RollingManifold;
using fourd::RollParams;
using fourd::ViewAxes;
using fourd::ViewPose;

double angle(const glm::dvec3& a, const glm::dvec3& b) {
  return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0));
}

// Rotate(theta, N) of §6.2 takes T's direction to T''s, about N = T x T' / |T x T'| (fixed), by
// theta = acos(T . T'), and is a rotation (R^T R = I, det 1). 1e-12: double rounding of a few
// products of unit vectors. Parallel: the identity; opposite: a half turn.
TEST(FourdRollingTest, RotateBetweenIsThePapersAxisAngle) {
  std::mt19937 rng(7);
  std::normal_distribution<double> g;
  for (int i = 0; i < 200; ++i) {
    const glm::dvec3 t(g(rng), g(rng), g(rng)), tp(g(rng), g(rng), g(rng));
    const glm::dmat3 r = fourd::rotate_between(t, 3.0 * tp);
    EXPECT_LT(glm::length(r * glm::normalize(t) - glm::normalize(tp)), 1e-12);
    const glm::dvec3 n = glm::normalize(glm::cross(t, tp));
    EXPECT_LT(glm::length(r * n - n), 1e-12);
    EXPECT_NEAR(fourd::rotation_angle_between(glm::dmat3(1.0), r), angle(t, tp), 1e-7);
    const glm::dmat3 e = glm::transpose(r) * r;
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(e[c][k], c == k ? 1.0 : 0.0, 1e-12);
    EXPECT_NEAR(glm::determinant(r), 1.0, 1e-12);
  }
  const glm::dvec3 t(0.3, -0.2, 0.9);
  EXPECT_EQ(fourd::rotate_between(t, 2.0 * t), glm::dmat3(1.0));
  EXPECT_LT(glm::length(fourd::rotate_between(t, -t) * t + t), 1e-12);
}

// Eq. 1 with beta = 3: |f| = alpha r^4 toward the line of sight through the screen centre, r the
// proxy's distance from that line; nothing along the line (the band pulls sideways, never into
// the surface under the probe); capped. The pose turns the line with the view. 1e-12 relative.
// Nearly opposite directions (pi - 1e-3 ... pi - 1e-9 rad), where T . T' can round below -1: the
// turn angle must come from atan2(|T x T'|, T . T'), finite everywhere (acos of a dot below -1
// is NaN). 2000 pairs in all directions; about 100 of them have a dot below -1.
TEST(FourdRollingTest, RotateBetweenNearlyOppositeDirectionsIsFinite) {
  int below_minus_one = 0;
  double worst = 0.0;
  for (int i = 0; i < 2000; ++i) {
    const glm::dvec3 v = glm::normalize(glm::dvec3(std::sin(i * 1.3), std::cos(i * 0.7), std::sin(i * 2.1 + 1)));
    const glm::dvec3 w = glm::normalize(glm::cross(v, glm::dvec3(0.3, 0.5, 0.8)));
    const double eps = std::pow(10.0, -3.0 - (i % 7));
    const glm::dvec3 b = glm::normalize(-v * std::cos(eps) + w * std::sin(eps));
    below_minus_one += glm::dot(v, b) < -1.0;
    const glm::dvec3 rv = fourd::rotate_between(v, b) * v;
    ASSERT_TRUE(std::isfinite(rv.x) && std::isfinite(rv.y) && std::isfinite(rv.z)) << "pair " << i << " eps " << eps;
    worst = std::max(worst, glm::length(rv - b));
  }
  EXPECT_GT(below_minus_one, 0) << "no pair tried the dot below -1";
  // The axis T x T' / |T x T'| of two nearly opposite unit vectors carries the cross product's
  // cancellation, ~1e-16 / eps: measured 1.1e-7 at eps = 1e-9.
  EXPECT_LT(worst, 1e-6);
}

TEST(FourdRollingTest, TetherIsEquationOneWithBetaThree) {
  RollParams p;
  p.on = true;
  p.tether_alpha_n_per_mm4 = 2e-4;
  p.tether_max_n = 1.5;
  ViewAxes axes{{1.0, 2.0, 3.0}, glm::normalize(glm::dvec3(0.0, -1.0, 1.0))};
  ViewPose pose;
  pose.rotation = fourd::rotate_between({0, 0, 1}, {1, 0, 1});
  pose.offset = {5.0, -4.0, 2.0};
  const glm::dvec3 centre = pose.to_world(axes.centre_ws), axis = pose.rotation * axes.toward_viewer_ws;
  const glm::dvec3 side = glm::normalize(glm::cross(axis, {0.3, 0.9, 0.1}));
  for (double r : {0.0, 2.0, 5.0, 8.0, 12.0}) {
    const glm::dvec3 proxy = centre + 7.0 * axis + r * side;
    const glm::dvec3 f = RollingManifold::tether_force(p, axes, pose, proxy);
    const double expected = std::min(2e-4 * std::pow(r, 4.0), 1.5);
    EXPECT_NEAR(glm::length(f), expected, 1e-12 * (1.0 + expected)) << "r " << r;
    if (r > 0.0) {
      EXPECT_LT(glm::length(glm::normalize(f) + side), 1e-12) << "toward the line";
    }
    EXPECT_NEAR(glm::dot(f, axis), 0.0, 1e-12);
  }
  p.on = false;
  EXPECT_EQ(RollingManifold::tether_force(p, axes, pose, centre + 5.0 * side), glm::dvec3(0.0));
}

// One step across an edge between two facets (a fold of 30 degrees about the y axis through the
// origin): with no smoothing the new facet faces the viewer at once (1e-12), the contact point
// keeps its place in the workspace (the hand does not jump; 1e-12 mm), and when the motion T (the
// step taken in the plane of the facet it leaves) crosses the edge at right angles Hanson & Zhang's
// rule alone does it (what is left to correct is
// under 1e-9 rad); crossing obliquely it leaves a tilt that the correction removes.
TEST(FourdRollingTest, CrossingAnEdgeTurnsTheNewFacetToTheViewerAboutTheContact) {
  const double fold = M_PI / 6;
  const glm::dvec3 n0(0, 0, 1), n1(-std::sin(fold), 0, std::cos(fold));  // facet 1 rises for x > 0
  const ViewAxes axes{{0, 0, 0}, {0, 0, 1}};
  for (double oblique : {0.0, 0.8}) {
    RollParams p;
    p.on = true;
    p.turn_s = 0.0;
    p.centre_s = 0.0;
    RollingManifold m;
    ViewPose pose;
    const glm::dvec3 before(-0.15, -0.15 * oblique, 0.0);
    ASSERT_TRUE(m.step(p, axes, {true, 0, before, n0}, 1e-3, pose));
    EXPECT_LT(angle(pose.rotation * axes.toward_viewer_ws, n0), 1e-12) << "facet 0 already faces the viewer";
    const glm::dvec3 after = glm::dvec3(0.15 * std::cos(fold), 0.15 * oblique, 0.15 * std::sin(fold));
    const glm::dvec3 after_ws = pose.to_workspace(after);
    // Hanson & Zhang's rule alone, for comparison.
    const glm::dvec3 step = after - before, t = step - glm::dot(step, n0) * n0, tp = t - glm::dot(t, n1) * n1;
    const glm::dmat3 seed = fourd::rotate_between(t, tp) * pose.rotation;
    const double left = angle(seed * axes.toward_viewer_ws, n1);
    ASSERT_TRUE(m.step(p, axes, {true, 1, after, n1}, 1e-3, pose));
    std::printf("T oblique %.1f: the paper's Rotate leaves %.3g rad; after the step %.3g rad\n", oblique, left,
                angle(pose.rotation * axes.toward_viewer_ws, n1));
    EXPECT_LT(angle(pose.rotation * axes.toward_viewer_ws, n1), 1e-12);
    EXPECT_LT(glm::length(pose.to_workspace(after) - after_ws), 1e-12);
    if (oblique == 0.0) EXPECT_LT(left, 1e-9);
    else EXPECT_GT(left, 0.01);
    EXPECT_EQ(m.turns(), 2);
  }
}

// An oblique crossing: Hanson & Zhang's Rotate(theta, N) takes T (the motion, in the facet it
// leaves) to T' (T projected on the new facet), so the motion keeps its direction in the workspace:
// target' ^T T' = target ^T T. The correction that then turns the new normal toward the viewer
// turns about T' itself (T' is normal to both the normal it moves and the new normal), so it
// keeps this exactly. T taken in the new facet's plane instead turns the motion by 0.13 rad here
// (measured).
TEST(FourdRollingTest, ObliqueCrossingKeepsTheMotionsDirectionInTheWorkspace) {
  const double fold = 40.0 * M_PI / 180.0;
  const glm::dvec3 n0(0, 0, 1), n1(-std::sin(fold), 0, std::cos(fold));  // facet 1 rises for x > 0
  const ViewAxes axes{{0, 0, 0}, {0, 0, 1}};
  RollParams p;
  p.on = true;
  p.turn_s = 0.0;
  RollingManifold m;
  ViewPose pose;
  const glm::dvec3 before(-0.5, -0.5, 0.0);
  ASSERT_TRUE(m.step(p, axes, {true, 0, before, n0}, 1e-3, pose));
  const glm::dmat3 target0 = m.target_rotation();
  const glm::dvec3 after(0.5, 0.5, 0.5 * std::tan(fold));
  ASSERT_TRUE(m.step(p, axes, {true, 1, after, n1}, 1e-3, pose));
  const glm::dvec3 step = after - before;
  const glm::dvec3 t = glm::normalize(step - glm::dot(step, n0) * n0);
  const glm::dvec3 tp = glm::normalize(t - glm::dot(t, n1) * n1);
  const glm::dvec3 motion_before = glm::transpose(target0) * t;
  const glm::dvec3 motion_after = glm::transpose(m.target_rotation()) * tp;
  // Rotations of unit vectors in double: a few ulps.
  EXPECT_LT(glm::length(motion_after - motion_before), 1e-12)
      << "T in the workspace (" << motion_before.x << ", " << motion_before.y << ", " << motion_before.z
      << ") became (" << motion_after.x << ", " << motion_after.y << ", " << motion_after.z << ")";
  EXPECT_LT(angle(m.target_rotation() * axes.toward_viewer_ws, n1), 1e-12);  // and the facet faces the viewer
}

// The haptic loop on the flat torus with the rolling manifold: a hand pressed 1 mm into the
// surface at the screen centre moves 25 mm sideways in its workspace and back, then holds.
struct RollRun {
  int turns = 0;                // interest-facet changes
  int roll_ticks = 0;           // ticks with an interest facet
  double max_angle = 0.0;       // facet normal vs the view's direction toward the viewer, rad
  double mean_angle = 0.0;
  double max_proxy_step_ws = 0.0;  // largest move of the proxy in the workspace in one tick, mm
  double max_turn = 0.0;        // largest turn of the view in one tick, rad
  double end_off_centre = 0.0;  // contact point's distance from the line of sight at the end
  double end_angle = 0.0;
  glm::dmat3 end_rotation{1.0};
};

RollRun roll_run(const std::vector<std::string>& extra) {
  RollRun out;
  // The camera looks at the surface point under the scene's probe, along its normal.
  auto base = load_scene(std::string(PS_SOURCE_DIR) + "/scenes/fourd/flat_torus.toml");
  EXPECT_TRUE(base) << base.error().message;
  auto hs0 = world::HapticScene::build(base.value());
  const world::Contact c0 = hs0.value().closest(base.value().probe.position, 20.0);
  EXPECT_TRUE(c0.hit);
  const glm::dvec3 n0 = glm::normalize(base.value().probe.position - c0.point);
  if (std::getenv("ROLL_DEBUG"))
    std::printf("c0 %.3f %.3f %.3f n0 %.5f %.5f %.5f\n", c0.point.x, c0.point.y, c0.point.z, n0.x, n0.y, n0.z);
  auto vec = [](const glm::dvec3& v) {
    char b[128];
    std::snprintf(b, sizeof b, "[%.17g,%.17g,%.17g]", v.x, v.y, v.z);
    return std::string(b);
  };
  std::vector<std::string> overrides = {"camera.target=" + vec(c0.point), "camera.position=" + vec(c0.point + 150.0 * n0),
                                        "surfaces.0.fourd_roll=true"};
  overrides.insert(overrides.end(), extra.begin(), extra.end());
  auto scene = load_scene(std::string(PS_SOURCE_DIR) + "/scenes/fourd/flat_torus.toml", overrides);
  EXPECT_TRUE(scene) << scene.error().message;
  auto hs = world::HapticScene::build(scene.value());
  EXPECT_TRUE(hs) << hs.error().message;
  const double r = scene.value().probe.radius_mm;
  const glm::dvec3 side = glm::normalize(glm::cross(n0, {0.0, 0.0, 1.0}));
  // Workspace path: approach (0.3 s), 25 mm sideways (2.5 s), back (1 s), hold (2.2 s).
  std::vector<DeviceSample> samples;
  const glm::dvec3 rest = c0.point + (r - 1.0) * n0;
  samples.push_back({0.0, c0.point + (r + 5.0) * n0, 0, true});
  samples.push_back({0.3, rest, 0, true});
  for (int i = 1; i <= 50; ++i) samples.push_back({0.3 + 2.5 * i / 50, rest + 25.0 * i / 50 * side, 0, true});
  for (int i = 1; i <= 20; ++i) samples.push_back({2.8 + 1.0 * i / 20, rest + 25.0 * (1.0 - i / 20.0) * side, 0, true});
  samples.push_back({6.0, rest, 0, true});
  LogDevice device(samples, true, "rolling walk");
  FakeClock clock;
  HapticLoop loop(device, clock, HapticLoopParams{}, &hs.value());
  const fourd::FourdTouch* touch = hs.value().fourd_touch(0);
  glm::dvec3 last_ws(0.0);
  glm::dmat3 last_rotation(1.0);
  bool have = false;
  double sum = 0.0;
  int last_facet = -1;
  const glm::dvec3 toward_viewer = n0;  // the file camera's, in the workspace
  for (int tick = 0; tick < 6000; ++tick) {
    loop.run_ticks(1);
    const HapticState st = loop.state().read();
    const glm::dvec3 ws = glm::transpose(st.view_rotation) * (st.proxy_mm - st.view_offset_mm);
    if (have && glm::length(ws - last_ws) > out.max_proxy_step_ws && std::getenv("ROLL_DEBUG"))
      std::printf("tick %d: proxy step %.3f mm, turn %.3f rad, facet %d, contact %d\n", tick, glm::length(ws - last_ws),
                  fourd::rotation_angle_between(last_rotation, st.view_rotation), st.roll_facet, int(st.in_contact));
    if (have) out.max_proxy_step_ws = std::max(out.max_proxy_step_ws, glm::length(ws - last_ws));
    if (have) out.max_turn = std::max(out.max_turn, fourd::rotation_angle_between(last_rotation, st.view_rotation));
    if (std::getenv("ROLL_DEBUG") && tick % 250 == 0) {
      const glm::dvec3 hand = glm::transpose(st.view_rotation) * (st.position_mm - st.view_offset_mm);
      std::printf("t %.2f hand_ws (%.1f %.1f %.1f) proxy_ws (%.1f %.1f %.1f) contact %d facet %d\n", tick * 1e-3, hand.x,
                  hand.y, hand.z, ws.x, ws.y, ws.z, int(st.in_contact), st.roll_facet);
    }
    last_ws = ws;
    last_rotation = st.view_rotation;
    have = true;
    if (st.roll_facet < 0) continue;
    if (st.roll_facet != last_facet && last_facet >= 0) ++out.turns;
    last_facet = st.roll_facet;
    // Independent of the manifold's own bookkeeping: the facet's winding normal from the touch
    // geometry against the published view turn applied to the file camera's direction.
    const glm::dvec3 n = touch->facet_normal(st.roll_facet), v = st.view_rotation * toward_viewer;
    const double a = std::acos(std::min(1.0, std::abs(glm::dot(n, v))));
    out.max_angle = std::max(out.max_angle, a);
    sum += a;
    ++out.roll_ticks;
    if (tick == 5999) {
      out.end_angle = a;
      const glm::dvec3 centre = st.view_rotation * c0.point + st.view_offset_mm;  // file target, in the world
      const glm::dvec3 contact = st.proxy_mm - r * v;  // the proxy rests on the facet, which faces v
      const glm::dvec3 d = contact - centre;
      out.end_off_centre = glm::length(d - glm::dot(d, v) * v);
    }
  }
  out.mean_angle = out.roll_ticks > 0 ? sum / out.roll_ticks : 0.0;
  out.end_rotation = loop.state().read().view_rotation;
  return out;
}

// Hanson & Zhang §6: "the facet of interest faces the viewer". With the turn at once (theirs) the
// touched facet's normal is the view direction to rounding at every tick (1e-6 rad: the
// published rotation is the product of some thousand turns, each exact to ~1e-15). With the
// default 80 ms smoothing it lags the turns: each leaves e^(-dt/80 ms) of itself when the next
// one comes, so turns of at most theta (the largest with the turn at once, 0.29 rad here) coming
// no faster than every 50 ms add up to at most theta / (1 - e^(-50/80)) = 2.2 theta (measured
// 0.35 rad, 1.2 theta); the mean stays small. The walk crosses many
// facets (the torus's facets are ~5 mm here). The view turns about the contact point, so the
// proxy (radius r, resting on the facet) moves in the workspace by at most r x the tick's turn
// plus the hand's own 0.01 mm a tick: with the turn at once that is a visible step (theirs),
// with the smoothing under 0.5 mm a tick;
// and after the hand is back at the centre and holds, the glide has brought the contact point
// to the line of sight through the screen centre (0.5 mm: e^(-2 s / 0.5 s) of a 25 mm walk
// leaves ~0.5 mm; measured far less) with its facet facing the viewer.
TEST(FourdRollingTest, WalkingTheFlatTorusKeepsTheTouchedFacetFacingTheViewer) {
  const RollRun off = roll_run({"surfaces.0.fourd_roll=false"});
  EXPECT_EQ(off.roll_ticks, 0);
  EXPECT_EQ(off.end_rotation, glm::dmat3(1.0)) << "no rolling: the view stays";
  std::printf("no rolling: the god-object's own largest step %.3f mm\n", off.max_proxy_step_ws);
  const RollRun at_once = roll_run({"surfaces.0.fourd_roll_turn_s=0"});
  std::printf("turn at once: %d facet changes over %d ticks, max angle %.3g rad, largest turn %.3f rad, "
              "proxy step <= %.3f mm, end: %.3f mm off centre\n",
              at_once.turns, at_once.roll_ticks, at_once.max_angle, at_once.max_turn, at_once.max_proxy_step_ws,
              at_once.end_off_centre);
  EXPECT_GE(at_once.turns, 10);
  EXPECT_GT(at_once.roll_ticks, 5000);
  EXPECT_LT(at_once.max_angle, 1e-6);
  EXPECT_LT(at_once.max_proxy_step_ws, off.max_proxy_step_ws + 3.0 * at_once.max_turn + 0.05)
      << "largest turn " << at_once.max_turn;
  EXPECT_LT(at_once.end_off_centre, 0.5);
  EXPECT_GT(fourd::rotation_angle_between(glm::dmat3(1.0), at_once.end_rotation), 0.2) << "the view rolled";

  const RollRun smooth = roll_run({});
  std::printf("80 ms turn: %d facet changes, max angle %.3f rad, mean %.4f rad, end angle %.2g rad, "
              "%.3f mm off centre, proxy step <= %.3f mm\n",
              smooth.turns, smooth.max_angle, smooth.mean_angle, smooth.end_angle, smooth.end_off_centre,
              smooth.max_proxy_step_ws);
  EXPECT_GE(smooth.turns, 10);
  EXPECT_LT(smooth.max_angle, 2.2 * at_once.max_turn);
  EXPECT_LT(smooth.mean_angle, 0.1);
  EXPECT_LT(smooth.end_angle, 1e-3);
  EXPECT_LT(smooth.end_off_centre, 0.5);
  EXPECT_LT(smooth.max_proxy_step_ws, off.max_proxy_step_ws + 0.1);

}

// The rolling flat torus and where its walks begin: the probe's start contact, the normal there,
// the direction the walks go (along the sheet, sideways on screen) and the probe's radius.
struct TorusStart {
  std::unique_ptr<world::HapticScene> felt;  // null: the scene did not load (the test says why)
  glm::dvec3 contact{0.0}, n{0.0}, side{0.0};
  double r = 0.0;
};

TorusStart torus_start() {
  TorusStart t;
  auto scene = load_scene(std::string(PS_SOURCE_DIR) + "/scenes/fourd/flat_torus_rolling.toml");
  EXPECT_TRUE(scene) << scene.error().message;
  if (!scene) return t;
  auto hs = world::HapticScene::build(scene.value());
  EXPECT_TRUE(hs) << hs.error().message;
  if (!hs) return t;
  const glm::dvec3 probe = scene.value().probe.position;
  const world::Contact c0 = hs.value().closest(probe, 20.0);
  EXPECT_TRUE(c0.hit);
  if (!c0.hit) return t;
  t.felt = std::make_unique<world::HapticScene>(std::move(hs.value()));
  t.contact = c0.point;
  t.n = glm::normalize(probe - c0.point);
  t.side = -glm::cross(t.n, glm::normalize(glm::cross(t.n, {0.0, 0.0, 1.0})));
  t.r = scene.value().probe.radius_mm;
  return t;
}

// The view rolls only with the hand: a hand that walks 25 mm pressed 3 mm into the rolling
// torus and then holds still, pressed, leaves the view where it is. Half a second after it
// stops (the filter's tail, the last turn ending) the view turns less than 1 degree over the
// next 3 s. Before the rest rule the glide moved the sheet under the held proxy onto the next
// facet, and the next: the window showed 61 to 130 degrees in 2 s.
TEST(FourdRollingTest, AHandHeldStillPressedDoesNotRollTheView) {
  const TorusStart ts = torus_start();
  ASSERT_TRUE(ts.felt);
  const glm::dvec3 &c0 = ts.contact, &n0 = ts.n, &side = ts.side;
  const double r = ts.r;
  const glm::dvec3 rest = c0 + (r - 3.0) * n0;
  std::vector<DeviceSample> samples;
  samples.push_back({0.0, c0 + (r + 5.0) * n0, 0, true});
  samples.push_back({0.3, rest, 0, true});
  for (int i = 1; i <= 50; ++i) samples.push_back({0.3 + 2.5 * i / 50, rest + 25.0 * i / 50 * side, 0, true});
  samples.push_back({10.0, rest + 25.0 * side, 0, true});
  LogDevice device(samples, true, "walk pressed, then hold");
  FakeClock clock;
  HapticLoop loop(device, clock, HapticLoopParams{}, ts.felt.get());
  loop.run_ticks(3300);  // the walk ends at 2.8 s; half a second more
  const HapticState held = loop.state().read();
  ASSERT_GT(fourd::rotation_angle_between(glm::dmat3(1.0), held.view_rotation), 0.05) << "the walk rolled the view";
  ASSERT_TRUE(held.in_contact) << "the hand holds pressed";
  loop.run_ticks(3000);
  const HapticState later = loop.state().read();
  const double turned = fourd::rotation_angle_between(held.view_rotation, later.view_rotation);
  std::printf("held still for 3 s: the view turned %.4f degrees, moved %.4f mm\n", glm::degrees(turned),
              glm::length(later.view_offset_mm - held.view_offset_mm));
  EXPECT_TRUE(later.in_contact);
  EXPECT_LT(turned, glm::radians(1.0));
  EXPECT_LT(glm::length(later.view_offset_mm - held.view_offset_mm), 0.5) << "no glide at rest either";
}

// run's Home key with the mouse (docs/window.md): the view goes back where the scene started
// and the hand and the proxy are put over the surface in that view in the same tick. Were the
// proxy left where the rolled view had it, it would be dragged through the torus to the hand,
// and that contact would turn the view away from home again (seen in the window: 2.3 mm off
// home after Home). A hand walks 25 mm over the torus (the view rolls), lifts 1.5 mm, and Home
// is pressed with the hand placed where the device is: from that tick on the view is home
// exactly and the proxy is where it was put, with no contact. (This walk was chosen because
// Home without the placement fails it: the dragged proxy touches on 20 ticks and the view ends
// 0.82 rad from home.)
TEST(FourdRollingTest, HomeWithAPlacementPutsViewAndProxyBackInOneTick) {
  const TorusStart ts = torus_start();
  ASSERT_TRUE(ts.felt);
  const glm::dvec3 &c0 = ts.contact, &n0 = ts.n, &side = ts.side;
  const double r = ts.r;
  const glm::dvec3 rest = c0 + (r - 1.0) * n0, lifted = rest + 25.0 * side + 1.5 * n0;
  std::vector<DeviceSample> samples;
  samples.push_back({0.0, c0 + (r + 5.0) * n0, 0, true});
  samples.push_back({0.3, rest, 0, true});
  for (int i = 1; i <= 50; ++i) samples.push_back({0.3 + 2.5 * i / 50, rest + 25.0 * i / 50 * side, 0, true});
  samples.push_back({3.0, lifted, 0, true});
  samples.push_back({10.0, lifted, 0, true});
  LogDevice device(samples, true, "walk, lift, Home");
  FakeClock clock;
  HapticLoop loop(device, clock, HapticLoopParams{}, ts.felt.get());
  loop.run_ticks(4000);
  HapticState st = loop.state().read();
  ASSERT_GT(fourd::rotation_angle_between(glm::dmat3(1.0), st.view_rotation), 0.05) << "the walk rolled the view";
  ASSERT_FALSE(st.in_contact) << "the lifted hand hovers";
  loop.request_view_home(lifted);
  loop.run_ticks(1);
  st = loop.state().read();
  EXPECT_EQ(st.view_rotation, glm::dmat3(1.0));
  EXPECT_EQ(st.view_offset_mm, glm::dvec3(0.0));
  EXPECT_LT(glm::length(st.proxy_mm - lifted), 1e-9) << "the proxy is put with the view, in the same tick";
  for (int tick = 0; tick < 500; ++tick) {
    loop.run_ticks(1);
    st = loop.state().read();
    ASSERT_FALSE(st.in_contact) << "tick " << tick << " after Home";
  }
  EXPECT_EQ(st.view_rotation, glm::dmat3(1.0)) << "no contact turned the view after Home";
  EXPECT_EQ(st.view_offset_mm, glm::dvec3(0.0));
}

}  // namespace
}  // namespace ps
