// Live reload and sweeps on a real context: a temp copy of glsl/ and of a scene is edited,
// the watcher notices, and the rebuilt renderer draws the change (or keeps the last good).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <glm/gtc/matrix_transform.hpp>

#include "prepare/prepare.h"
#include "render/scene_frames.h"
#include "scene/scene_io.h"
#include "support/gl_test.h"
#include "tune/overrides_file.h"
#include "tune/sweep.h"
#include "tune/tune_session.h"

namespace ps {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& p) {
  std::ifstream f(p);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

// Rewrites a file with one substring replaced; the mtime is bumped explicitly so the change
// is seen even on a file system with coarse timestamps.
void replace_in_file(const fs::path& p, const std::string& from, const std::string& to) {
  std::string text = read_text(p);
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from << " not in " << p;
  text.replace(at, from.size(), to);
  const auto before = fs::last_write_time(p);
  std::ofstream(p, std::ios::trunc) << text;
  fs::last_write_time(p, before + std::chrono::seconds(1));
}

class TuneGLTest : public test::GlTest {
 protected:
  void SetUp() override {
    test::GlTest::SetUp();
    dir_ = fs::path(testing::TempDir()) / ("tune_gl_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    fs::copy(PS_SOURCE_DIR "/glsl", dir_ / "glsl", fs::copy_options::recursive);
    scene_ = dir_ / "scene.toml";
    fs::copy(PS_SOURCE_DIR "/scenes/table4_1_a.toml", scene_);
  }
  // table4_1_a is sparse (n 2-6): "auto" keeps its naive sum, so the tile tests ask for "baked".
  static constexpr const char* kBaked = "materials.table4_1_a.gabor_strategy=baked";
  std::unique_ptr<TuneSession> open_session(std::vector<std::string> sets = {}) {
    sets.insert(sets.begin(), "render.size=[64,64]");
    TuneSource src;
    src.scene_path = scene_.string();
    src.overrides = sets;
    src.renderer.glsl_root = (dir_ / "glsl").string();
    auto s = TuneSession::open(src);
    EXPECT_TRUE(s) << (s ? "" : s.error().message);
    return s ? std::move(s.value()) : nullptr;
  }
  static Image frame(TuneSession& s) {
    EXPECT_TRUE(s.renderer().render_frame());
    return s.renderer().read_color();
  }
  fs::path dir_, scene_;
};

TEST_P(TuneGLTest, ReloadPicksUpAShaderChange) {
  auto s = open_session({kBaked});
  ASSERT_TRUE(s);
  const Image before = frame(*s);
  EXPECT_FALSE(s->reload_if_changed());
  replace_in_file(dir_ / "glsl/surface.frag", "o_color = vec4(pow(", "o_color = vec4(0.5 * pow(");
  ASSERT_TRUE(s->reload_if_changed());
  EXPECT_EQ(s->last_error(), "");
  EXPECT_EQ(s->generation(), 2);
  EXPECT_GT(s->renderer().stats().bake_ms, 0.0);  // a shader changed: the tile is baked again
  const Image after = frame(*s);
  ASSERT_EQ(after.pixels.size(), before.pixels.size());
  for (std::size_t i = 0; i < after.pixels.size(); i += 97)  // halved, up to 8-bit rounding
    EXPECT_NEAR(after.pixels[i], 0.5f * before.pixels[i], 1.01f / 255.0f) << i;
}

TEST_P(TuneGLTest, ReloadPicksUpASceneChangeAndKeepsTheProbe) {
  auto s = open_session({kBaked});
  ASSERT_TRUE(s);
  const glm::dvec3 probe{1.0, 2.0, 16.0};
  s->view().probe.position = probe;
  s->view().probe.velocity = {500.0, 0.0, 0.0};
  const Image before = frame(*s);
  replace_in_file(scene_, "albedo = [0.85, 0.85, 0.85]", "albedo = [0.2, 0.85, 0.85]");
  ASSERT_TRUE(s->reload_if_changed());
  EXPECT_EQ(s->last_error(), "");
  EXPECT_EQ(s->view().probe.position, probe);
  EXPECT_EQ(s->renderer().probe().position, probe);  // the view it draws is the session's
  EXPECT_EQ(s->renderer().stats().bake_ms, 0.0);  // only the albedo changed: the tile is shared
  const Image after = frame(*s);
  EXPECT_NE(after.pixels, before.pixels);
}

TEST_P(TuneGLTest, BrokenShaderKeepsTheLastGoodImageAndRecovers) {
  auto s = open_session();
  ASSERT_TRUE(s);
  const Image good = frame(*s);
  const fs::path lib = dir_ / "glsl/lib/pseudo_shadow.glsl";
  const std::string original = read_text(lib);
  replace_in_file(lib, "if (d <= 0.0) return 1.0;", "if (d <= 0.0) return 1.0 +;");
  ASSERT_TRUE(s->reload_if_changed());
  EXPECT_NE(s->last_error().find("pseudo_shadow.glsl:14"), std::string::npos) << s->last_error();
  EXPECT_EQ(s->generation(), 1);
  EXPECT_EQ(frame(*s).pixels, good.pixels);  // the old renderer keeps running
  replace_in_file(lib, "if (d <= 0.0) return 1.0 +;", "if (d <= 0.0) return 1.0;");
  ASSERT_TRUE(s->reload_if_changed());
  EXPECT_EQ(s->last_error(), "");
  EXPECT_EQ(frame(*s).pixels, good.pixels);
}

TEST_P(TuneGLTest, BadSetKeepsTheRendererAndNamesTheKey) {
  auto s = open_session();
  ASSERT_TRUE(s);
  Status st = s->set("materials.table4_1_a.lamda_min", "1.0");
  ASSERT_FALSE(st);
  EXPECT_NE(st.error().message.find("close matches: lambda_min"), std::string::npos) << st.error().message;
  EXPECT_TRUE(s->edits().empty());
  ASSERT_TRUE(s->set("materials.table4_1_a.lambda_min", "1.0"));
  EXPECT_EQ(s->edits().size(), 1u);
}

// `run` rebuilds its haptic scene when the edits moved, comparing one number a frame
// (TuneSession::edits_generation): a set that changes an edit moves it; a failed set, the same
// value again, a reload and a curve edit (tables are not edits()) leave it.
TEST_P(TuneGLTest, TheEditsGenerationMovesWithTheEdits) {
  auto s = open_session();
  ASSERT_TRUE(s);
  EXPECT_EQ(s->edits_generation(), 0u);
  ASSERT_FALSE(s->set("materials.table4_1_a.lamda_min", "1.0"));
  EXPECT_EQ(s->edits_generation(), 0u);
  ASSERT_TRUE(s->set("materials.table4_1_a.lambda_min", "1.0"));
  EXPECT_EQ(s->edits_generation(), 1u);
  ASSERT_TRUE(s->set("materials.table4_1_a.lambda_min", "1.0"));
  ASSERT_TRUE(s->reload());
  const Lut table{LutAxis::kDistanceMm, {{0.0, 0.9}, {5.0, 0.2}}, {}};
  ASSERT_TRUE(s->set_curve("materials.table4_1_a.intensity_lut", table));
  EXPECT_EQ(s->edits_generation(), 1u);
  ASSERT_TRUE(s->set("materials.table4_1_a.lambda_min", "1.5"));
  EXPECT_EQ(s->edits_generation(), 2u);
}

// Curves edited in the panel (TuneSession::set_curve) are saved with the overrides as table files
// next to them, and `--overrides` reads them back: the same tables, the same image, byte for byte.
TEST_P(TuneGLTest, EditedCurvesRoundTripThroughTheOverrides) {
  auto s = open_session();
  ASSERT_TRUE(s);
  Lut intensity{LutAxis::kDistanceMm, {{0.0, 0.9}, {2.0, 0.6}, {5.0, 0.25}, {50.0, 0.125}}, {}};
  Lut gain{LutAxis::kSpeedMmS, {{0.0, 0.5}, {100.0, 1.0}, {400.0, 0.0625}}, {}};
  ASSERT_TRUE(s->set("materials.table4_1_a.lambda_min", "1.0"));
  ASSERT_TRUE(s->set_curve("materials.table4_1_a.intensity_lut", intensity));
  ASSERT_TRUE(s->set_curve("materials.table4_1_a.speed_gain_lut", gain));
  const Status bad = s->set_curve("materials.nope.intensity_lut", intensity);
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("materials.nope.intensity_lut: no such material curve"), std::string::npos);
  EXPECT_EQ(s->curve_edits().size(), 2u);
  EXPECT_EQ(s->renderer().scene().materials[0].intensity_lut, intensity);
  const Image before = frame(*s);
  ASSERT_TRUE(s->save_overrides());

  const fs::path overrides = dir_ / "scene.overrides.toml";
  const std::string text = read_text(overrides);
  EXPECT_NE(text.find("materials.table4_1_a.intensity_lut = \"scene.table4_1_a.intensity.lut\"\n"), std::string::npos) << text;
  EXPECT_NE(text.find("materials.table4_1_a.speed_gain_lut = \"scene.table4_1_a.speed_gain.lut\"\n"), std::string::npos) << text;
  EXPECT_TRUE(fs::is_regular_file(dir_ / "scene.table4_1_a.intensity.lut"));
  auto lines = read_overrides(overrides.string());
  ASSERT_TRUE(lines) << lines.error().message;
  auto again = open_session(lines.value());
  ASSERT_TRUE(again);
  const Material& m = again->renderer().scene().materials[0];
  // Rows with short decimal forms print (%.9g) and parse back to the same doubles: exact.
  EXPECT_EQ(m.intensity_lut, intensity);
  EXPECT_EQ(m.speed_gain_lut, gain);
  EXPECT_EQ(m.gabor.lambda_min_mm, 1.0);
  const Image after = frame(*again);
  EXPECT_EQ(after.pixels, before.pixels);

  // Dropping an edit restores the scene's curve (and the image changes: the table was in it).
  ASSERT_TRUE(s->set_curve("materials.table4_1_a.intensity_lut", Lut{}));
  EXPECT_TRUE(s->renderer().scene().materials[0].intensity_lut.empty());
  EXPECT_NE(frame(*s).pixels, before.pixels);
}

// A 3x3 sweep: the sheet has the right size and each cell is exactly the single render.
TEST_P(TuneGLTest, SweepCellsMatchSingleRenders) {
  SweepJob job;
  job.scene_path = scene_.string();
  job.overrides = {"render.size=[48,48]"};
  job.axes = {parse_sweep("materials.table4_1_a.lambda_min=1:2:3").value(),
              parse_sweep("probe.velocity=[0,0,0],[250,0,0],[500,0,0]").value()};
  auto cells = render_sweep(job, {});
  ASSERT_TRUE(cells) << cells.error().message;
  ASSERT_EQ(cells->size(), 9u);
  const Image sheet = sweep_sheet(job.axes, cells.value());
  // Each label wrapped to the 48 px cell (contact_sheet), the label rows as tall as the longest.
  std::size_t label_lines = 1;
  for (const auto& c : cells.value()) label_lines = std::max(label_lines, wrap_text(c.label, 48).size());
  EXPECT_GT(label_lines, 1u);  // "materials.table4_1_a.lambda_min=1 mm probe.velocity=..." is wider than 48 px
  const int pad = ContactSheetDesc{}.padding, label_h = (kGlyphHeight + 2) * static_cast<int>(label_lines);
  EXPECT_EQ(sheet.width, pad + 3 * (48 + pad));
  EXPECT_EQ(sheet.height, pad + 3 * (48 + label_h + pad));
  for (int i : {0, 4, 8}) {
    const auto& cell = cells.value()[i];
    auto scene = load_scene(job.scene_path, {"render.size=[48,48]",
                                             job.axes[0].key + "=" + job.axes[0].values[cell.index[0]],
                                             "probe.velocity=" + job.axes[1].values[cell.index[1]]});
    ASSERT_TRUE(scene);
    RendererOptions one_frame;  // what `render` passes for its one frame
    one_frame.expected_frames = 1;
    auto single = Renderer::create(scene.value(), one_frame);
    ASSERT_TRUE(single);
    ASSERT_TRUE(single.value()->render_frame());
    const Image ref = single.value()->read_color();
    const int cx = pad + i % 3 * (48 + pad), cy = pad + i / 3 * (48 + label_h + pad);
    for (int y = 0; y < 48; ++y)
      for (int x = 0; x < 48; ++x)
        for (int c = 0; c < 3; ++c) ASSERT_EQ(sheet.at(cx + x, cy + y, c), ref.at(x, y, c)) << i << " " << x << "," << y;
  }
}

// Strategy "baked" bakes table4_1_a's texture into a tile when the renderer is created. A tuning
// edit that leaves the material's Gabor values alone must share that tile (no second bake, the
// same image as a fresh session with the edit); an edit of a Gabor value must bake again.
TEST_P(TuneGLTest, SetSharesTheBakedTileUnlessTheTextureChanges) {
  auto s = open_session({kBaked});
  ASSERT_TRUE(s);
  ASSERT_GT(s->renderer().stats().bake_ms, 0.0) << "table4_1_a is expected to get a baked tile";
  ASSERT_TRUE(s->set("light.ambient", "0.5"));
  EXPECT_EQ(s->renderer().stats().bake_ms, 0.0);
  const Image shared = frame(*s);
  TuneSource fresh_src;
  fresh_src.scene_path = scene_.string();
  fresh_src.overrides = {"render.size=[64,64]", kBaked, "light.ambient=0.5"};
  fresh_src.renderer.glsl_root = (dir_ / "glsl").string();
  auto fresh = TuneSession::open(fresh_src);
  ASSERT_TRUE(fresh) << fresh.error().message;
  EXPECT_GT(fresh.value()->renderer().stats().bake_ms, 0.0);
  EXPECT_EQ(frame(*fresh.value()).pixels, shared.pixels);
  ASSERT_TRUE(s->set("materials.table4_1_a.a_min", "0.5"));  // a range [0.5, 1]: another texture
  ASSERT_TRUE(s->set("materials.table4_1_a.a_max", "0.5"));  // all 0.5: half of it, still baked
  EXPECT_GT(s->renderer().stats().bake_ms, 0.0);
}

// An edit (a panel value, a 4D turn) rebuilds the renderer while a [navigation] or rolling view
// has moved the camera. The frames after it, under the same pose, must show the same camera,
// and the view back home (the haptic loop's restart, Home) the camera the scene started with.
// Keeping the moved camera as the new renderer's own carried the pose twice: the picture
// stayed turned after Home (seen in the rolling flat torus after a press and a 4D turn).
TEST_P(TuneGLTest, AnEditWhileTheViewIsMovedKeepsTheCameraWithTheView) {
  auto s = open_session({kBaked});
  ASSERT_TRUE(s);
  const Camera home = s->renderer().camera();
  FrameInput moved;
  moved.view = ViewPose{{5.0, -3.0, 2.0}, glm::dmat3(glm::rotate(glm::dmat4(1.0), 0.4, glm::dvec3(0.3, 1.0, 0.2)))};
  ASSERT_TRUE(s->renderer().render(moved));
  const Camera before = s->renderer().camera();
  ASSERT_GT(glm::length(before.position - home.position), 1.0);
  ASSERT_TRUE(s->set("light.ambient", "0.5"));
  ASSERT_TRUE(s->renderer().render(moved));
  auto expect_camera = [](const Camera& got, const Camera& want, const char* what) {
    // 1e-9 mm: the same rotation applied and taken off again, in doubles.
    EXPECT_LT(glm::length(got.position - want.position), 1e-9) << what;
    EXPECT_LT(glm::length(got.target - want.target), 1e-9) << what;
    EXPECT_LT(glm::length(got.up - want.up), 1e-9) << what;
  };
  expect_camera(s->renderer().camera(), before, "after the edit, the same pose");
  ASSERT_TRUE(s->renderer().render(FrameInput{}));  // no pose change: the camera stays
  FrameInput back;
  back.view = ViewPose{};
  ASSERT_TRUE(s->renderer().render(back));
  expect_camera(s->renderer().camera(), home, "the view back home");
}

// The view is the session's: a rebuilt renderer draws it as it stands, with nothing copied from the
// old renderer. A file reload keeps the flags, the orbited camera and the probe (the same image
// again, from the new renderer's first frame as from the old one's); a `set` keeps the flags and
// the camera and restarts the probe from the scene; a camera.* key restarts the camera too.
TEST_P(TuneGLTest, ARebuiltRendererDrawsTheSessionsView) {
  auto s = open_session({kBaked});
  ASSERT_TRUE(s);
  const glm::dvec3 start_probe = s->renderer().scene().probe.position;
  const ViewFlags shown{true, false, true};
  s->view().show = shown;
  s->view().camera.position += glm::dvec3(30.0, -20.0, 0.0);  // an orbit
  const Camera orbited = s->view().camera;
  const glm::dvec3 hover{5.0, -4.0, 40.0};  // 15 mm above the plane, inside the onset: no push
  s->view().probe.position = hover;
  const Image before = frame(*s);
  ASSERT_EQ(s->view().probe.position, hover) << "the frame pushed the probe";
  const Renderer* old = &s->renderer();
  ASSERT_TRUE(s->reload());
  ASSERT_NE(&s->renderer(), old);
  EXPECT_EQ(&s->renderer().view(), &s->view()) << "the new renderer draws the session's view";
  EXPECT_EQ(s->view().show, shown);
  EXPECT_EQ(s->view().camera.position, orbited.position);
  EXPECT_EQ(s->view().probe.position, hover);
  EXPECT_EQ(frame(*s).pixels, before.pixels) << "the same view, drawn by the new renderer";

  ASSERT_TRUE(s->set("light.ambient", "0.3"));  // the scene's value: the same look
  EXPECT_EQ(s->view().show, shown);
  EXPECT_EQ(s->view().camera.position, orbited.position);
  EXPECT_EQ(s->view().probe.position, start_probe) << "a set restarts the probe";
  ASSERT_TRUE(s->set("camera.fov_y_deg", "40"));
  EXPECT_EQ(s->view().camera.position, s->renderer().scene().camera.position) << "a camera key restarts it";
  EXPECT_EQ(s->view().show, shown);
}

// A scene switch (a button's, in `run`: a new TuneSession of the new scene) starts from the new
// scene's view, not the old one's: its camera, its probe, the command line's flags, and the world
// where the scene starts it, so its first frame is the one `render` draws of it (bodies included).
TEST_P(TuneGLTest, ASceneSwitchStartsFromTheNewScenesView) {
  auto old = open_session({kBaked});
  ASSERT_TRUE(old);
  old->view().show = ViewFlags{true, true, true};
  old->view().camera.position += glm::dvec3(30.0, -20.0, 0.0);
  const std::vector<std::string> sets{"render.size=[96,96]"};
  const std::string demo = PS_SOURCE_DIR "/scenes/fields_bodies_demo.toml";
  auto switched = TuneSession::open({demo, sets, {}, {}, ViewFlags{false, false, true}});
  ASSERT_TRUE(switched) << switched.error().message;
  TuneSession& s = *switched.value();
  const Scene& scene = s.renderer().scene();
  EXPECT_EQ(s.view().camera.position, scene.camera.position);
  EXPECT_EQ(s.view().probe.position, scene.probe.position);
  EXPECT_EQ(s.view().show, (ViewFlags{false, false, true}));
  ASSERT_FALSE(scene.bodies.empty());
  EXPECT_EQ(s.view().bodies_mm, start_positions(scene));
  EXPECT_FALSE(s.view().markers.empty()) << "the charges";
  s.view().show = ViewFlags{};  // as `render` draws it
  ASSERT_TRUE(s.renderer().render_frame());
  auto loaded = load_scene(demo, sets);
  ASSERT_TRUE(loaded) << loaded.error().message;
  auto cli = open_renderer(loaded.value(), {});
  ASSERT_TRUE(cli) << cli.error().message;
  ASSERT_TRUE(render_scene_frames(*cli.value(), 1));
  EXPECT_EQ(s.renderer().read_color().pixels, cli.value()->read_color().pixels);
}

PS_INSTANTIATE_HEADLESS_BACKENDS(TuneGLTest);

}  // namespace
}  // namespace ps
