// A world switch through `replay`'s own session code (replay_session), on both headless backends:
// pressing the control panel's Weight button (tests/haptics/data/universe_to_weight.traj) switches
// to weight.toml, and no frame draws the new world with the old world's probe (issue 42). The
// switch's frame used to be drawn by Weight's renderer from the state before the haptic tick that
// adopted Weight: the panel's press, 2-3 mm into its button's pocket, shown in the new world.
#include <gtest/gtest.h>

#include <memory>
#include <optional>

#include "app/session/session.h"
#include "devices/sample_log.h"
#include "prepare/prepare.h"
#include "scene/scene_io.h"
#include "support/gl_test.h"
#include "world/haptic_scene.h"

namespace ps {
namespace {

class UniverseSwitchGLTest : public test::GlTest {};

struct World {
  std::shared_ptr<const world::HapticScene> haptic;
  std::unique_ptr<Renderer> renderer;
};

World open_world(const std::string& file) {
  World w;
  auto scene = load_scene(std::string(PS_SOURCE_DIR) + "/scenes/universe/" + file,
                          {"render.size=[96,96]", "render.depth_map_size=64"});
  EXPECT_TRUE(scene) << scene.error().message;
  if (!scene) return w;
  auto haptic = world::HapticScene::build(scene.value());
  EXPECT_TRUE(haptic) << haptic.error().message;
  if (haptic) w.haptic = std::make_shared<const world::HapticScene>(std::move(haptic.value()));
  auto renderer = open_renderer(scene.value(), {}, {.button_pictures = false});
  EXPECT_TRUE(renderer) << renderer.error().message;
  if (renderer) w.renderer = std::move(renderer.value());
  return w;
}

// How deep a probe centred at p sits in `scene`'s geometry (0: free).
double buried_mm(const world::HapticScene& scene, const glm::dvec3& p) {
  const double r = scene.probe_radius_mm();
  const world::Contact c = scene.closest(p, r);
  return c.hit ? std::max(0.0, r - c.distance_mm) : 0.0;
}

// Every frame Weight's renderer draws shows a state from the tick that adopted Weight or later
// (scene_serial 1: the loop's first replace_scene), with the proxy free of Weight's geometry (the
// god-object's 1e-3 mm epsilon, read back: 0.05 mm, walk_checks.py's BURIED_TOL_MM) and the drawn
// probe penetrating it by at most 0.25 mm (a tessellated surface's chord under the true one, as
// walk_checks.py's PENETRATION_TOL_MM). The panel's frames go on to the frame before the switch.
TEST_P(UniverseSwitchGLTest, NoFrameDrawsTheNewWorldWithTheOldWorldsProbe) {
  World panel = open_world("panel.toml"), weight = open_world("weight.toml");
  ASSERT_TRUE(panel.renderer && panel.haptic && weight.renderer && weight.haptic);
  auto log = load_sample_log(std::string(PS_SOURCE_DIR) + "/tests/haptics/data/universe_to_weight.traj");
  ASSERT_TRUE(log) << log.error().message;
  LogDevice device(log.value(), true, "trajectory");
  ReplayOptions opt;
  opt.fps = 30.0;
  opt.haptic_scene = panel.haptic.get();
  opt.switch_scene = [&](const std::string& path) -> Result<SceneSwitch> {
    EXPECT_NE(path.find("weight.toml"), std::string::npos) << path;
    return SceneSwitch{weight.renderer.get(), weight.haptic};
  };
  int panel_frames = 0, weight_frames = 0;
  std::optional<double> switched_at;
  opt.on_event = [&](const HapticEvent& e) {
    if (e.kind == EventKind::scene_switched) switched_at = e.time_s;
  };
  auto r = replay_session(*panel.renderer, device, opt, [&](int i, double t, const HapticState& st, const Renderer& rr) {
    if (&rr == panel.renderer.get()) {
      ++panel_frames;
      EXPECT_EQ(st.scene_serial, 0u) << "frame " << i;
      return ok_status();
    }
    ++weight_frames;
    EXPECT_EQ(st.scene_serial, 1u) << "frame " << i << " at " << t << " s: a state from before Weight";
    EXPECT_LE(buried_mm(*weight.haptic, st.proxy_mm), 0.05) << "frame " << i;
    EXPECT_LE(rr.stats().max_penetration_mm, 0.25) << "frame " << i;
    return ok_status();
  });
  ASSERT_TRUE(r) << r.error().message;
  ASSERT_TRUE(switched_at.has_value()) << "the press switched to Weight";
  EXPECT_GT(panel_frames, 5);
  EXPECT_GT(weight_frames, 5);
}

PS_INSTANTIATE_HEADLESS_BACKENDS(UniverseSwitchGLTest);

}  // namespace
}  // namespace ps
