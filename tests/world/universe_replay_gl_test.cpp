// The Virtual Universe's worlds through `replay`'s own session code (replay_session: the haptic
// loop on a fake clock, frames rendered), on both headless backends, with the scripted
// trajectories under tests/haptics/data. Poly: pressing dents the drawn surface by the drawn
// probe's sink, the pseudo-shadow's depth follows the dent (the probe does not penetrate what is
// drawn), the springs bring the surface back after the probe leaves, and a violent trajectory
// makes no NaN and no dent past the bound.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <random>

#include "app/session/session.h"
#include "devices/sample_log.h"
#include "prepare/prepare.h"
#include "scene/scene_io.h"
#include "support/gl_test.h"
#include "world/deformable.h"
#include "world/deformable_surfaces.h"
#include "world/haptic_scene.h"

namespace ps {
namespace {

class UniverseReplayGLTest : public test::GlTest {};

std::string universe(const std::string& name) { return std::string(PS_SOURCE_DIR) + "/scenes/universe/" + name; }
std::string data(const std::string& name) { return std::string(PS_SOURCE_DIR) + "/tests/haptics/data/" + name; }

bool finite3(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// A universe scene opened for a replay: the scene (with `sets`), its haptic scene and a renderer
// without button pictures. `expected_frames` > 0: a short replay draws the per-pixel texture sum
// instead of baking a tile.
struct World {
  Scene scene;
  std::optional<world::HapticScene> haptic;
  std::unique_ptr<Renderer> renderer;
};

World open_world(const std::string& file, const std::vector<std::string>& sets, int expected_frames = 0) {
  World w;
  auto scene = load_scene(universe(file), sets);
  EXPECT_TRUE(scene) << scene.error().message;
  if (!scene) return w;
  w.scene = scene.value();
  auto haptic = world::HapticScene::build(w.scene);
  EXPECT_TRUE(haptic) << haptic.error().message;
  if (haptic) w.haptic.emplace(std::move(haptic.value()));
  RendererOptions ro;
  ro.expected_frames = expected_frames;
  auto renderer = open_renderer(w.scene, ro, {.button_pictures = false});
  EXPECT_TRUE(renderer) << renderer.error().message;
  if (renderer) w.renderer = std::move(renderer.value());
  return w;
}

// Replays `traj` (a file of tests/haptics/data, interpolated) on `w` at `fps`.
void replay_world(World& w, const std::string& traj, double fps, const FrameSink& sink,
                  std::function<void(const HapticEvent&)> on_event = {}) {
  ASSERT_TRUE(w.renderer && w.haptic);
  auto log = load_sample_log(data(traj));
  ASSERT_TRUE(log) << log.error().message;
  LogDevice device(log.value(), true, "trajectory");
  ReplayOptions opt;
  opt.fps = fps;
  opt.haptic_scene = &*w.haptic;
  opt.on_event = std::move(on_event);
  auto r = replay_session(*w.renderer, device, opt, sink);
  ASSERT_TRUE(r) << r.error().message;
}

struct PolyFrame {
  double t = 0.0;
  HapticState state;
  DeformationStats deformation;
  double penetration_mm = 0.0;
  glm::dvec3 drawn{0.0};
};

struct PolyRun {
  World world;
  std::vector<PolyFrame> frames;
};

PolyRun replay_poly(Device& device) {
  PolyRun run;
  run.world = open_world("poly.toml", {"render.size=[96,96]", "render.depth_map_size=64"});
  if (!run.world.renderer || !run.world.haptic) return run;
  ReplayOptions opt;
  opt.fps = 30.0;
  opt.haptic_scene = &*run.world.haptic;
  auto r = replay_session(*run.world.renderer, device, opt, [&](int, double t, const HapticState& s, const Renderer& rr) {
    run.frames.push_back({t, s, rr.deformation(), rr.stats().max_penetration_mm, rr.stats().probe_position});
    return ok_status();
  });
  EXPECT_TRUE(r) << (r ? "" : r.error().message);
  return run;
}

// tests/haptics/data/universe_poly_press.traj: down onto the head's top, held 0.6 s, lifted.
// While held (t in [0.6, 1.0] s), the drawn probe sinks by k_c / (k_c + k) = 0.5 / 0.8 of the
// hand's depth (computed here from the published device and proxy positions, not by the code
// under test), and the dent's deepest vertex is that sink less the contact overlap, to 0.6 mm
// (a vertex beside the probe's lowest point sits higher on its sphere: 0.54 mm for a vertex
// 2.5 mm off, half the longest edge after one split). What is drawn follows: the drawn probe
// penetrates the drawn surface by at most 0.6 mm (the 0.15 mm overlap, a facet's chord sagging
// into the sphere, and a texel of the 64^2 probe depth map on a sloped surface; measured 0.47),
// where the same probe over the undented surface penetrates by its sink, to 0.3 mm. One
// second after the probe left, every vertex is exactly back at rest.
TEST_P(UniverseReplayGLTest, PolyDentsUnderTheProbeAndSpringsBack) {
  auto log = load_sample_log(data("universe_poly_press.traj"));
  ASSERT_TRUE(log) << log.error().message;
  LogDevice device(log.value(), true, "trajectory");
  PolyRun run = replay_poly(device);
  ASSERT_GT(run.frames.size(), 60u);
  int held = 0;
  glm::dvec3 deepest_drawn(0.0);
  double deepest_sink = 0.0;
  for (const PolyFrame& f : run.frames) {
    ASSERT_TRUE(f.deformation.finite) << f.t;
    ASSERT_TRUE(finite3(f.drawn)) << f.t;
    if (f.t < 0.6 || f.t > 1.0) continue;
    ++held;
    ASSERT_TRUE(f.state.in_contact) << f.t;
    ASSERT_EQ(f.state.contact_surface, 0) << f.t;
    const double hand_depth = glm::length(f.state.position_mm - f.state.proxy_mm);
    const double sink = std::min(0.5 / (0.5 + 0.3) * hand_depth, 3.0);
    EXPECT_GT(sink, 1.0) << f.t;
    EXPECT_LE(f.deformation.max_displacement_mm, sink - world::kContactOverlapMm + 1e-6) << f.t;
    EXPECT_GE(f.deformation.max_displacement_mm, sink - world::kContactOverlapMm - 0.6) << f.t;
    EXPECT_LT(f.penetration_mm, 0.6) << f.t;
    EXPECT_GT(f.deformation.constrained, 0) << f.t;
    if (sink > deepest_sink) deepest_sink = sink, deepest_drawn = f.drawn;
  }
  EXPECT_GE(held, 10);
  const PolyFrame& last = run.frames.back();
  EXPECT_GT(last.t, 2.2);
  EXPECT_FALSE(last.state.in_contact);
  EXPECT_EQ(last.deformation.max_displacement_mm, 0.0);
  // While dented the surface is uploaded every frame; once back at rest with the probe away,
  // nothing is (no vertex moved: world::DeformableSurfaces::step marks no mesh changed, so none is uploaded).
  for (const PolyFrame& f : run.frames) {
    if (f.t >= 0.6 && f.t <= 1.0) {
      EXPECT_EQ(f.deformation.uploaded, 1) << f.t;
    }
  }
  EXPECT_EQ(last.deformation.uploaded, 0);

  // The same drawn probe over Suzanne undented.
  World rigid = open_world("poly.toml", {"render.size=[96,96]", "render.depth_map_size=64", "surfaces.0.deformable=false"});
  ASSERT_TRUE(rigid.renderer);
  ASSERT_TRUE(rigid.renderer->render(probe_frame_input(deepest_drawn, glm::dvec3(0.0))));
  EXPECT_GT(rigid.renderer->stats().max_penetration_mm, deepest_sink - 0.3) << "sink " << deepest_sink;
}

// A violent trajectory: 1.5 s of jumps to random points in and around the head every 5 ms (the
// sanitizer follows at its 5 mm per tick, so the hand ends up deep inside). No NaN anywhere, the
// dent never deeper than deform_max_mm, the drawn probe never more than half its radius into
// the felt surface; and the dent is gone 1 s after the hand is taken away.
TEST_P(UniverseReplayGLTest, PolySurvivesAViolentTrajectory) {
  std::vector<DeviceSample> samples;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> pos(-45.0, 45.0);
  for (int i = 0; i <= 300; ++i) samples.push_back({i * 0.005, {pos(rng), pos(rng), pos(rng)}, 0, true});
  samples.push_back({1.6, {0.0, 0.0, 60.0}, 0, true});
  samples.push_back({2.6, {0.0, 0.0, 60.0}, 0, true});
  LogDevice device(samples, false, "violent");
  PolyRun run = replay_poly(device);
  int touching = 0;
  for (const PolyFrame& f : run.frames) {
    ASSERT_TRUE(f.deformation.finite) << f.t;
    ASSERT_TRUE(finite3(f.drawn)) << f.t;
    EXPECT_LE(f.deformation.max_displacement_mm, 6.0) << f.t;
    EXPECT_LE(glm::length(f.state.proxy_mm - world::pressed_position(run.world.scene, f.state.contact_surface,
                                                                     f.state.proxy_mm, f.state.position_mm, 0.5)),
              3.0 + 1e-9);
    touching += f.deformation.constrained > 0;
  }
  EXPECT_GT(touching, 3) << "the trajectory should have pressed the head";
  EXPECT_EQ(run.frames.back().deformation.max_displacement_mm, 0.0);
}

// The deformable surfaces are the world's, stepped by their owner (a session's drive_frame, through
// step_deformation); the renderer only draws them. Poly with a world settled apart: creating a
// renderer on it steps nothing; frames that move the drawn probe onto Suzanne's crown and away
// with no step leave the world's version and vertices exactly as they were, and the second and
// third are incremental (nothing but the probe changed: no mesh was uploaded); one step of the
// world by its owner, pressing there, is drawn by the next frame (a full redraw: the mesh was
// uploaded; the renderer's vertices are the world's, dented). A second renderer given the same
// world draws it as it stands, with no settling of its own.
TEST_P(UniverseReplayGLTest, TheRendererDrawsTheDeformationItsOwnerStepsAndNeverStepsIt) {
  auto scene = load_scene(universe("poly.toml"), {"render.size=[96,96]", "render.depth_map_size=64"});
  ASSERT_TRUE(scene) << scene.error().message;
  auto view = make_view(scene.value());  // the session's: its deformable surfaces settled
  ASSERT_TRUE(view && view.value()->deformables) << (view ? "no deformable surface" : view.error().message);
  const std::shared_ptr<world::DeformableSurfaces> surfaces = view.value()->deformables;
  ASSERT_EQ(surfaces->drawn().size(), 1u);
  const int poly = surfaces->drawn()[0].surface;
  const std::uint64_t version = surfaces->drawn()[0].version;
  const std::vector<glm::dvec3> before = surfaces->positions(poly);
  // The crown: the drawn mesh's highest vertex; the probe pressed 2 mm into it.
  glm::dvec3 crown(0.0, 0.0, -1e9);
  for (const glm::dvec3& v : before)
    if (v.z > crown.z) crown = v;
  Probe pressing = scene->probe;
  pressing.position = crown + glm::dvec3(0.0, 0.0, pressing.radius_mm - 2.0);

  RendererOptions ro;
  ro.expected_frames = 8;
  ro.view = view.value();
  auto made = open_renderer(scene.value(), ro, {.button_pictures = false});
  ASSERT_TRUE(made) << made.error().message;
  Renderer& r = *made.value();
  EXPECT_EQ(r.view().deformables, surfaces);
  for (const glm::dvec3& at : {pressing.position, crown + glm::dvec3(8.0, 0.0, 20.0), pressing.position}) {
    FrameInput in;
    in.probe = ProbeMotion{at, glm::dvec3(0.0)};
    ASSERT_TRUE(r.render(in));
  }
  EXPECT_EQ(surfaces->drawn()[0].version, version) << "a frame stepped the world";
  EXPECT_EQ(surfaces->positions(poly), before);
  EXPECT_TRUE(r.stats().incremental) << "a frame uploaded a mesh nobody stepped";

  surfaces->advance(10.0, pressing);  // sets the session clock
  surfaces->advance(10.1, pressing);  // 0.1 s pressed
  ASSERT_EQ(surfaces->drawn()[0].version, version + 1);
  FrameInput in;
  in.probe = ProbeMotion{pressing.position, glm::dvec3(0.0)};
  ASSERT_TRUE(r.render(in));
  EXPECT_FALSE(r.stats().incremental) << "the stepped mesh should have been uploaded";
  EXPECT_EQ(r.stats().deformation.uploaded, 1);
  EXPECT_GT(r.stats().deformation.max_displacement_mm, 0.5);
  EXPECT_EQ(r.deformed_vertices(poly), surfaces->positions(poly));
  EXPECT_NE(r.deformed_vertices(poly), before);

  auto second = open_renderer(scene.value(), ro, {.button_pictures = false});  // ro holds the same world
  ASSERT_TRUE(second) << second.error().message;
  EXPECT_EQ(surfaces->drawn()[0].version, version + 1) << "creating a renderer stepped the world";
  EXPECT_EQ(second.value()->deformed_vertices(poly), surfaces->positions(poly));
}

// Weight through replay (tests/haptics/data/universe_weight_drop.traj: the hand lowered to z =
// 45 mm and held): after its first impact with the hand still the ball rises to the apex that its restitution
// predicts. The prediction is integrated here, independently (RK4, 10 us steps), from the floor
// at e x the impact speed the body_impact event reports, under gravity and the band's two-sided
// spring to the held hand and its air drag (air_damping_per_s), the scene's own constants. The replay's apex is the highest of its
// 200 fps frames; tolerance 0.3 mm + 2 %: a frame within 2.5 ms of the apex is at most
// a/2 (2.5 ms)^2 = 0.06 mm below it at the ~20 m/s^2 there, the impact is caught at the end of
// its 1 ms tick, and the loop's velocity Verlet is second order at 1 ms.
TEST_P(UniverseReplayGLTest, WeightsFirstBounceRisesAsItsRestitutionSays) {
  World w = open_world("weight.toml", {"render.size=[48,48]", "render.depth_map_size=32"});
  std::vector<HapticEvent> impacts;
  std::vector<std::pair<double, double>> z;  // frame time, ball height
  replay_world(
      w, "universe_weight_drop.traj", 200.0,
      [&](int, double t, const HapticState& s, const Renderer&) {
        z.emplace_back(t, s.body_mm[0].z);
        return ok_status();
      },
      [&](const HapticEvent& e) {
        if (e.kind == EventKind::body_impact) impacts.push_back(e);
      });
  // The first impact once the hand is still (it lands at 0.3 s), and the one after it.
  std::size_t first = 0;
  while (first < impacts.size() && impacts[first].time_s <= 0.3) ++first;
  ASSERT_LT(first + 1, impacts.size()) << "two impacts after 0.3 s expected";
  const HapticEvent& hit = impacts[first];
  const double t_hit = hit.time_s, t_next = impacts[first + 1].time_s;
  double apex = -1e9;
  for (const auto& [t, h] : z)
    if (t > t_hit && t < t_next) apex = std::max(apex, h);

  const Body& b = w.scene.bodies[0];
  const double e = b.restitution, k = b.spring_n_per_mm, m = b.mass_g, L = b.rest_length_mm;
  const double g = w.scene.fields[0].acceleration_mm_s2.z, hand = 45.0, floor_z = b.floor_z_mm + b.radius_mm;
  const double drag = b.air_damping_per_s;
  auto accel = [&](double zz, double vv) { return g + k * ((hand - zz) - L) * 1e6 / m - drag * vv; };
  double zz = floor_z, v = e * hit.value;
  const double h = 1e-5;
  while (v > 0.0) {
    const double k1z = v, k1v = accel(zz, v);
    const double k2z = v + 0.5 * h * k1v, k2v = accel(zz + 0.5 * h * k1z, k2z);
    const double k3z = v + 0.5 * h * k2v, k3v = accel(zz + 0.5 * h * k2z, k3z);
    const double k4z = v + h * k3v, k4v = accel(zz + h * k3z, k4z);
    zz += h / 6.0 * (k1z + 2 * k2z + 2 * k3z + k4z);
    v += h / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
  }
  const double rise = zz - floor_z;
  EXPECT_GT(rise, 2.0) << "a real bounce";
  EXPECT_NEAR(apex - floor_z, rise, 0.3 + 0.02 * rise) << "impact at " << hit.value << " mm/s, t " << t_hit;
}

// Field's box through replay (tests/haptics/data/universe_field_navigate.traj): the camera moves
// with the view's offset (its target is the file's plus the offset), the pointer still maps
// through the camera as the file has it (the mouse moves the hand in the workspace), the frames
// change while the view travels and not once it has stopped (1.6 s and 2.0 s: the same bytes).
TEST_P(UniverseReplayGLTest, FieldsViewTravelsWithTheBox) {
  // The box the trajectory was written for (field.toml's is narrower now: UniverseMouseGLTest).
  World w = open_world("field.toml", {"render.size=[64,64]", "render.depth_map_size=32",
                                      "navigation.box_size_mm=[130,100,60]"});
  std::vector<Image> frames;
  glm::dvec3 offset(0.0);
  replay_world(w, "universe_field_navigate.traj", 10.0, [&](int, double, const HapticState& s, const Renderer& rr) {
    frames.push_back(rr.read_color());
    offset = s.view_offset_mm;
    return ok_status();
  });
  ASSERT_EQ(frames.size(), 21u);
  EXPECT_GT(offset.x, 140.0);
  const Camera& cam = w.renderer->camera();
  EXPECT_EQ(cam.target, w.scene.camera.target + offset);
  EXPECT_EQ(cam.position, w.scene.camera.position + offset);
  const PointerView view = pointer_view(*w.renderer, pointer_plane(*w.renderer));
  EXPECT_NEAR(glm::length(view.camera.position - w.scene.camera.position), 0.0, 1e-9);
  EXPECT_NEAR(glm::length(view.camera.target - w.scene.camera.target), 0.0, 1e-9);
  EXPECT_FALSE(frames[2].pixels == frames[10].pixels) << "the view should have moved";
  EXPECT_TRUE(frames[16].pixels == frames[20].pixels) << "the view should have stopped";
}

// Illusion through replay (tests/haptics/data/universe_illusion_slide.traj: pressed 2 mm into
// the sphere's top, slid 40 mm along x). The drawn probe (after the renderer's own push-out)
// travels 1.6 times the felt proxy's x range across the top (1 %: the stretch is exact near the
// object, and the renderer's push-out of the drawn probe is along the surface normal, tenths of
// a millimetre at most here);
// a solid material keeps the drawn probe out of the drawn ellipsoid (un-stretched, it is at
// least r + R from the centre, to 0.01 mm), while water lets it in (A Virtual Universe §3: a
// non-compliant material "made it seem harder").
TEST_P(UniverseReplayGLTest, IllusionStretchesThePathAndSolidsKeepTheProbeOut) {
  auto replay = [&](const std::string& material, double& felt_x, double& drawn_x, double& min_gap) {
    World w = open_world("illusion.toml",
                         {"render.size=[64,64]", "render.depth_map_size=32", "surfaces.0.material=\"" + material + "\""},
                         61);
    const Surface& sphere = w.scene.surfaces[0];
    const double reach = sphere.radius_mm + w.scene.probe.radius_mm;
    double f_lo = 1e9, f_hi = -1e9, d_lo = 1e9, d_hi = -1e9;
    min_gap = 1e9;
    replay_world(w, "universe_illusion_slide.traj", 30.0, [&](int, double t, const HapticState& s, const Renderer& rr) {
      const glm::dvec3 drawn = rr.stats().probe_position;
      const glm::dvec3 unstretched = sphere.center + (drawn - sphere.center) / sphere.visual_stretch;
      min_gap = std::min(min_gap, glm::length(unstretched - sphere.center) - reach);
      if (t >= 0.5 && t <= 1.5) {
        f_lo = std::min(f_lo, s.proxy_mm.x), f_hi = std::max(f_hi, s.proxy_mm.x);
        d_lo = std::min(d_lo, drawn.x), d_hi = std::max(d_hi, drawn.x);
      }
      return ok_status();
    });
    felt_x = f_hi - f_lo;
    drawn_x = d_hi - d_lo;
  };
  double felt = 0.0, drawn = 0.0, gap = 0.0;
  replay("plastic", felt, drawn, gap);
  EXPECT_GT(felt, 30.0);
  EXPECT_NEAR(drawn / felt, 1.6, 0.016);
  EXPECT_GT(gap, -0.01) << "a solid keeps the drawn probe out of the drawn ellipsoid";
  RecordProperty("plastic_drawn_over_felt", std::to_string(drawn / felt));
  replay("water", felt, drawn, gap);
  EXPECT_LT(gap, -1.5) << "water lets the probe in";
}

// Field through replay (tests/haptics/data/universe_field_points.traj): held still at three
// points, the fields' force the loop publishes is the softened Coulomb sum of the file's charges
// at the probe (the god-object proxy, which the coupling holds F / k_c from the hand; 1e-9
// relative: the same law in another order, at the proxy of one tick earlier, which has stopped
// moving), and at the weak spot it is under 1 % of the force 10 mm away.
TEST_P(UniverseReplayGLTest, FieldsForceIsTheCoulombSumAndVanishesAtTheWeakSpot) {
  World w = open_world("field.toml", {"render.size=[48,48]", "render.depth_map_size=32"});
  std::map<int, HapticState> at;  // frame index -> state
  replay_world(w, "universe_field_points.traj", 10.0, [&](int i, double, const HapticState& s, const Renderer&) {
    at[i] = s;
    return ok_status();
  });
  auto coulomb = [&](const glm::dvec3& p) {
    glm::dvec3 f(0.0);
    for (const Field& c : w.scene.fields) {
      const glm::dvec3 d = p - c.position;
      f += c.charge_n_mm2 * d / std::pow(glm::dot(d, d) + c.softening_mm * c.softening_mm, 1.5);
    }
    return f;
  };
  for (int frame : {4, 10, 16}) {  // the ends of the three holds
    const HapticState& s = at.at(frame);
    const glm::dvec3 want = coulomb(s.proxy_mm);
    EXPECT_GT(glm::length(want), 0.01);
    EXPECT_EQ(s.view_offset_mm, glm::dvec3(0.0)) << "inside the box";
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(s.field_force_n[k], want[k], 1e-9 * glm::length(want)) << frame;
  }
  const HapticState& weak = at.at(24);
  EXPECT_NEAR(weak.proxy_mm.y, -9.8, 0.05);
  EXPECT_LT(glm::length(weak.field_force_n), 0.01 * glm::length(coulomb(weak.proxy_mm + glm::dvec3(10, 0, 0))));
}

PS_INSTANTIATE_HEADLESS_BACKENDS(UniverseReplayGLTest);

}  // namespace
}  // namespace ps
