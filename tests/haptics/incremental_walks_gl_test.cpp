// Incremental frames (render/frame_key.h) over the shipped walks: each walk is replayed twice,
// with RendererOptions::incremental on and off, and every frame's colour image, every AOV and
// the numbers the reductions give must be the same bits (tolerance zero: an incremental frame
// keeps pixels whose inputs are the same bytes, and redraws the rest with the same draws; a
// pixel's value never depends on the scissor box it was drawn in). The walks are taken from
// tools/byte_identity.sh's list: a still camera over a plank, a mesh, a 4D surface, buttons,
// a falling body, a dented polygon (deformation), a view that moves, and one with overlays
// drawn.
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/session/session.h"
#include "devices/sample_log.h"
#include "render/aov.h"
#include "scene/scene_io.h"
#include "support/expect_reductions.h"
#include "support/gl_test.h"
#include "world/haptic_scene.h"

namespace ps {
namespace {

class IncrementalWalksGLTest : public test::GlTest {};

struct Walk {
  std::string name, scene, trajectory;  // scene empty: the built-in default
  double fps = 20.0;
  bool overlays = false;  // --show-probe --show-device
};

const std::vector<Walk>& walks() {
  static const std::vector<Walk> w = {
      {"stroke", "", "tests/haptics/data/stroke.traj", 30.0},
      {"stroke_overlays", "", "tests/haptics/data/stroke.traj", 30.0, true},
      {"monkey_head", "scenes/table5_1_monkey_head.toml", "tests/app/data/monkey_head.traj", 4.0},
      {"flat_torus_stroke", "scenes/fourd/flat_torus.toml", "tests/fourd/data/flat_torus_stroke.traj", 12.0},
      {"press_buttons", "scenes/buttons_demo.toml", "tests/haptics/data/press_buttons.traj", 15.0},
      {"weight_drop", "scenes/universe/weight.toml", "tests/haptics/data/universe_weight_drop.traj", 20.0},
      {"poly_press", "scenes/universe/poly.toml", "tests/haptics/data/universe_poly_press.traj", 20.0},
      {"stroke_r25", "scenes/table4_1_a.toml", "tests/vibration/data/stroke_r25.traj", 15.0},
      {"field_navigate", "scenes/universe/field.toml", "tests/haptics/data/universe_field_navigate.traj", 20.0},
  };
  return w;
}

// One frame as the tests compare it: colour, every AOV, the reductions' numbers; and what
// must make it a full redraw when it changed since the last frame.
struct Frame {
  std::vector<Image> images;
  FrameStats stats;
  std::vector<glm::dvec3> deformed, bodies;  // every deformable surface's vertices; the bodies
  glm::dvec3 eye{0.0}, target{0.0};
};

Frame take(const Renderer& r, const HapticState& st) {
  Frame f{{r.read_color()}, r.stats(), {}, {st.body_mm.begin(), st.body_mm.begin() + st.body_count},
          r.camera().position, r.camera().target};
  for (size_t i = 0; i < r.scene().surfaces.size(); ++i) {
    const std::vector<glm::dvec3> v = r.deformed_vertices(static_cast<int>(i));
    f.deformed.insert(f.deformed.end(), v.begin(), v.end());
  }
  for (const std::string& aov : aov_names()) {
    auto img = r.read_aov(aov);
    EXPECT_TRUE(img.ok()) << aov;
    if (img) f.images.push_back(std::move(img.value()));
  }
  return f;
}

Scene walk_scene(const Walk& w) {
  const std::vector<std::string> size = {"render.size=[128,128]"};  // byte_identity.sh's replays
  auto s = w.scene.empty() ? parse_scene(default_scene_text(), "<default>", default_scene_base_dir(), size)
                           : load_scene(std::string(PS_SOURCE_DIR) + "/" + w.scene, size);
  EXPECT_TRUE(s.ok()) << w.name << ": " << (s.ok() ? "" : s.error().message);
  return s.ok() ? s.value() : Scene{};
}

std::vector<Frame> replay_frames(const Walk& w, bool incremental) {
  const Scene scene = walk_scene(w);
  RendererOptions options;
  options.expected_frames = 60;  // as a replay of this length: the same tile choice both ways
  options.incremental = incremental;
  auto view = make_view(scene, ViewFlags{w.overlays, false, w.overlays});
  EXPECT_TRUE(view.ok()) << w.name;
  if (!view.ok()) return {};
  options.view = view.value();
  auto renderer = Renderer::create(scene, options);
  EXPECT_TRUE(renderer.ok()) << w.name << ": " << (renderer.ok() ? "" : renderer.error().message);
  if (!renderer.ok()) return {};
  auto device = open_log_device("trajectory:" + std::string(PS_SOURCE_DIR) + "/" + w.trajectory);
  auto haptic = world::HapticScene::build(scene);
  EXPECT_TRUE(device.ok() && haptic.ok()) << w.name;
  if (!device.ok() || !haptic.ok()) return {};
  ReplayOptions opt;
  opt.fps = w.fps;
  opt.haptic_scene = &haptic.value();
  std::vector<Frame> frames;
  auto r = replay_session(*renderer.value(), *device.value(), opt, [&](int, double, const HapticState& st, const Renderer& rr) {
    frames.push_back(take(rr, st));
    return ok_status();
  });
  EXPECT_TRUE(r.ok()) << w.name << ": " << (r.ok() ? "" : r.error().message);
  return frames;
}

// Bitwise (NaN equals NaN of the same bits): the number of differing values.
int differing_values(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels) return -1;
  int n = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) n += std::memcmp(&a.pixels[i], &b.pixels[i], sizeof(float)) != 0;
  return n;
}

void expect_same(const Frame& inc, const Frame& full, const std::string& where) {
  ASSERT_EQ(inc.images.size(), full.images.size()) << where;
  for (size_t i = 0; i < inc.images.size(); ++i)
    EXPECT_EQ(differing_values(inc.images[i], full.images[i]), 0)
        << where << (i == 0 ? std::string(" colour") : " AOV " + aov_names()[i - 1]);
  const FrameStats &s = inc.stats, &t = full.stats;
  test::expect_same_reductions(s, t, where);
  EXPECT_EQ(s.speed_gain, t.speed_gain) << where;
  EXPECT_FALSE(t.incremental) << where;
  EXPECT_EQ(t.drawn_pixels, 128 * 128) << where;
}

// Causes of a full redraw seen in the walks, counted.
struct Causes {
  int camera = 0, deformation = 0, bodies = 0;
};

// A frame whose camera, dented mesh or bodies changed since the last one redraws everything.
void expect_full_when_changed(const Frame& now, const Frame& last, const std::string& where, Causes& seen) {
  const bool camera = now.eye != last.eye || now.target != last.target;
  const bool deformed = now.deformed != last.deformed, bodies = now.bodies != last.bodies;
  seen.camera += camera;
  seen.deformation += deformed;
  seen.bodies += bodies;
  if (camera || deformed || bodies) {
    EXPECT_FALSE(now.stats.incremental) << where << ": camera " << camera << ", mesh " << deformed << ", bodies " << bodies;
  }
}

TEST_P(IncrementalWalksGLTest, EveryFrameEqualsTheFullRedrawBitForBit) {
  int incremental = 0, shadowed_incremental = 0;
  Causes seen;
  for (const Walk& w : walks()) {
    const std::vector<Frame> inc = replay_frames(w, true), full = replay_frames(w, false);
    ASSERT_EQ(inc.size(), full.size()) << w.name;
    ASSERT_GE(inc.size(), 5u) << w.name;
    for (size_t f = 0; f < inc.size(); ++f) {
      const std::string where = w.name + " frame " + std::to_string(f);
      expect_same(inc[f], full[f], where);
      if (f > 0) expect_full_when_changed(inc[f], inc[f - 1], where, seen);
      if (!inc[f].stats.incremental) continue;
      ++incremental;
      if (inc[f].stats.shadow_pixels > 0) ++shadowed_incremental;
      EXPECT_FALSE(w.overlays) << w.name << " frame " << f << ": overlays make every next frame full";
    }
  }
  // The comparison saw incremental frames, and pseudo-shadows in them (counts from a run: the
  // walks move the camera or a body now and then, which redraws everything).
  EXPECT_GE(incremental, 200);  // a run: 410 of them, 389 with a pseudo-shadow
  EXPECT_GE(shadowed_incremental, 150);
  std::printf("incremental frames: %d, with a pseudo-shadow: %d; full redraws for camera %d, mesh %d, bodies %d\n",
              incremental, shadowed_incremental, seen.camera, seen.deformation, seen.bodies);
  EXPECT_GE(seen.deformation, 1);  // poly_press dents its polygon
  EXPECT_GE(seen.bodies, 1);       // weight_drop's weight falls
  EXPECT_GE(seen.camera, 1);       // field_navigate moves the view
}

PS_INSTANTIATE_HEADLESS_BACKENDS(IncrementalWalksGLTest);

}  // namespace
}  // namespace ps
