// The Gabor tile baked in bands between frames (RendererOptions::bake_slice_ms, the window)
// against the tile baked whole at creation (headless): the first frame comes before the bake
// ends and is textured, frames keep coming, and once the tile is done the frames are the
// headless ones, byte for byte. Counted in frames, never timed.
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/scenes.h"
#include "render/renderer.h"
#include "render/tile_bake.h"
#include "support/gl_test.h"

namespace ps {
namespace {

class TileBakeGLTest : public test::GlTest {};

// flat_plane_scene with a textured, baked material touched by a big probe (a wide textured
// footprint). 16 samples per lambda_min: the tile is within 1 % sigma RMS of the per-pixel sum
// (GaborGLTest.BakedTextureMatchesItsCpuTwinAndTheNaiveTexture). Point-sampled unless
// `filter` says otherwise (then the tile has filtered levels, baked after level 0).
Scene baked_scene(GaborParams::Filter filter = GaborParams::Filter::kNone) {
  Scene s = test::flat_plane_scene(14.5);
  s.probe.radius_mm = 15.0;
  Material& m = s.materials[0];
  m.gabor.lambda_min_mm = 0.8;
  m.gabor.lambda_max_mm = 2.0;
  m.gabor.theta_max_rad = 1.0;
  m.gabor.strategy = GaborParams::Strategy::kBaked;
  m.gabor.bake_samples_per_lambda = 16;
  m.onset_distance_mm = 100.0;  // texture everywhere under the probe
  m.gabor.filter = filter;
  return s;
}

// One frame at the scene's probe state (the previous frame's push-out undone, so every frame
// draws the same view).
void frame(Renderer& r, const Scene& s) {
  ASSERT_TRUE(r.render(probe_frame_input(s.probe.position, s.probe.velocity)).ok());
}

// RMS difference of the texture AOV (sigmas) over the pixels both frames shadow.
double texture_rms(const Renderer& a, const Renderer& b, int* pixels) {
  const Image ta = a.read_aov("texture").value(), tb = b.read_aov("texture").value();
  const Image ia = a.read_aov("intensity").value();
  double sum2 = 0.0;
  *pixels = 0;
  for (int y = 0; y < ta.height; ++y)
    for (int x = 0; x < ta.width; ++x) {
      if (ia.at(x, y, 0) <= 0.0f) continue;
      const double d = ta.at(x, y, 0) - tb.at(x, y, 0);
      sum2 += d * d;
      ++*pixels;
    }
  return std::sqrt(sum2 / std::max(*pixels, 1));
}

TEST_P(TileBakeGLTest, HeadlessRenderBakesTheWholeTileBeforeItsFirstFrame) {
  const Scene s = baked_scene();
  auto made = Renderer::create(s, {});
  ASSERT_TRUE(made.ok()) << made.error().message;
  Renderer& r = *made.value();
  EXPECT_EQ(r.stats().bake_progress, 1.0);
  EXPECT_GE(r.stats().tiles_ready_ms, 0.0);
  EXPECT_GT(r.stats().bake_ms, 0.0);
  frame(r, s);
  EXPECT_EQ(r.stats().frames_before_tiles, 0);
  EXPECT_GT(r.stats().first_frame_ms, r.stats().tiles_ready_ms);
}

// "auto" with a known number of frames (render, tune cells, replay): the tile is baked only
// when the frames' per-pixel work (frames x width x height, every pixel counted) exceeds the
// tile's texels^2; at the boundary and below the frames draw the per-pixel sum and nothing is
// baked. The tile's size is read from the note of a renderer that bakes it.
TEST_P(TileBakeGLTest, AutoBakesOnlyWhenTheFramesNeedMoreWorkThanTheTile) {
  Scene s = baked_scene();
  s.materials[0].gabor.strategy = GaborParams::Strategy::kAuto;
  s.render.width = s.render.height = 64;
  s.camera.projection = Projection::kOrthographic;
  s.camera.ortho_height_mm = 100.0;
  auto note_of = [](const Renderer& r) {
    for (const std::string& n : r.stats().skipped)
      if (n.find("material") != std::string::npos) return n;
    return std::string();
  };
  auto make = [&](int frames) {
    RendererOptions o;
    o.expected_frames = frames;
    auto made = Renderer::create(s, o);
    EXPECT_TRUE(made.ok()) << made.error().message;
    frame(*made.value(), s);
    return std::move(made.value());
  };
  const auto open_ended = make(0);
  const std::string baked_note = note_of(*open_ended);
  int texels = 0;
  ASSERT_EQ(std::sscanf(baked_note.c_str() + baked_note.find("baked "), "baked %d^2", &texels), 1) << baked_note;
  EXPECT_GT(open_ended->stats().bake_ms, 0.0);
  // The textured-pixel bound, in closed form: the window is the probe's bounding diameter
  // (sphere r = 15 mm: 30 mm) at 64 px / 100 mm, squared (1e-9: a product of doubles).
  const double per_frame = (30.0 * 0.64) * (30.0 * 0.64);
  EXPECT_NEAR(open_ended->textured_pixels_per_frame(), per_frame, 1e-9);
  const int boundary = static_cast<int>(std::floor(static_cast<double>(texels) * texels / per_frame));
  for (int frames : {1, boundary}) {
    const auto r = make(frames);
    EXPECT_EQ(r->stats().bake_ms, 0.0) << frames;
    EXPECT_NE(note_of(*r).find("naive Gabor sum (" + std::to_string(frames) + " frame"), std::string::npos)
        << note_of(*r);
  }
  const auto many = make(boundary + 1);
  EXPECT_GT(many->stats().bake_ms, 0.0);
  EXPECT_EQ(note_of(*many), baked_note);
}

// The sliced bake of `s`'s tile, every level of it, against the whole one. interim_rms: the
// bound on the interim frames' texture (the per-pixel sum) against the tile's.
void check_sliced_bake(const Scene& s, double interim_rms) {
  RendererOptions sliced;
  // Far below any band's time: after the first band (16 rows) every band has the minimum
  // height (8 rows), so the count of frames is fixed by the tile's size, not by the clock.
  sliced.bake_slice_ms = 1e-6;
  auto made = Renderer::create(s, sliced);
  ASSERT_TRUE(made.ok()) << made.error().message;
  Renderer& r = *made.value();
  const GaborBakePlan plan = r.gabor_bake_plan(0);
  const int texels = plan.texels;
  ASSERT_TRUE(plan.ok);
  EXPECT_EQ(r.stats().bake_progress, 0.0) << "create() must not bake when sliced";
  EXPECT_EQ(r.stats().tiles_ready_ms, -1.0);

  frame(r, s);
  const FrameStats first = r.stats();
  EXPECT_EQ(first.frames_before_tiles, 1);
  EXPECT_GT(first.bake_progress, 0.0);
  EXPECT_LT(first.bake_progress, 1.0);
  EXPECT_GE(first.first_frame_ms, 0.0);
  EXPECT_EQ(first.tiles_ready_ms, -1.0);
  // Not black: the shadow is there, and textured like the tile will be.
  EXPECT_GT(first.shadow_pixels, 5000u);
  auto whole = Renderer::create(s, {});
  ASSERT_TRUE(whole.ok()) << whole.error().message;
  frame(*whole.value(), s);
  int pixels = 0;
  const double rms = texture_rms(r, *whole.value(), &pixels);
  EXPECT_GT(pixels, 5000);
  std::printf("interim texture vs the tile's: %.4f sigma RMS over %d pixels\n", rms, pixels);
  EXPECT_LT(rms, interim_rms) << "the interim texture must be the tile's texture";
  EXPECT_GT(rms, 0.0) << "the first frame must draw the per-pixel sum, not the tile";

  // The stats the --stats JSON carries say the same.
  const auto json = nlohmann::json::parse(stats_json(first, "test", "test", "test", 1));
  EXPECT_TRUE(json["gabor_tiles_ready_ms"].is_null());
  EXPECT_EQ(json["frames_before_tiles"], 1);
  EXPECT_DOUBLE_EQ(json["gabor_bake_progress"].get<double>(), first.bake_progress);

  // 16 rows, then 8 per frame: ceil((texels - 16) / 8) more frames finish level 0, then each
  // filtered level L takes ceil(texels_L / 8) (a band never spans two levels).
  int expected_frames = 1 + (texels - 16 + 7) / 8;
  for (int level = 1; level <= plan.filtered_levels; ++level) expected_frames += (plan.level_texels(level) + 7) / 8;
  int frames = 1;
  double progress = first.bake_progress;
  while (r.stats().bake_progress < 1.0 && frames < 2 * expected_frames) {
    frame(r, s);
    ++frames;
    EXPECT_GT(r.stats().bake_progress, progress);
    progress = r.stats().bake_progress;
  }
  EXPECT_EQ(frames, expected_frames);
  EXPECT_EQ(r.stats().bake_progress, 1.0);
  // Every frame but the one that baked the last band drew with the sum; that one, the tile.
  EXPECT_EQ(r.stats().frames_before_tiles, expected_frames - 1);
  EXPECT_GT(r.stats().tiles_ready_ms, r.stats().first_frame_ms);
  const auto done = nlohmann::json::parse(stats_json(r.stats(), "test", "test", "test", frames));
  EXPECT_LT(done["first_frame_ms"].get<double>(), done["gabor_tiles_ready_ms"].get<double>());

  // From here on the tile: the same frame as the headless renderer's, byte for byte.
  frame(r, s);
  frame(*whole.value(), s);
  EXPECT_EQ(r.read_color().pixels, whole.value()->read_color().pixels);
  EXPECT_EQ(r.read_aov("texture").value().pixels, whole.value()->read_aov("texture").value().pixels);
}

TEST_P(TileBakeGLTest, SlicedBakeDrawsFramesBeforeTheTileThenTheHeadlessFrame) {
  // Per-pixel sum against the 16-samples tile: the tile's error, < 1 % sigma RMS (above).
  check_sliced_bake(baked_scene(), 0.01);
}

TEST_P(TileBakeGLTest, SlicedBakeOfFilteredLevelsEndsOnTheHeadlessFrame) {
  const Scene s = baked_scene(GaborParams::Filter::kAnalytic);
  ASSERT_GT(make_gabor_bake_plan(s.materials[0].gabor, make_gabor_setup(s.materials[0].gabor)).filtered_levels, 2);
  // The interim frames draw the analytic filter, the tile its levels blended to match it at
  // the mean wavelength (1.4 mm) while this texture's wavelengths span 0.8-2 mm: measured
  // 0.109 sigma RMS apart at 2.6-6.4 px per wavelength (each is within ~0.05 sigma of the
  // supersampled reference at a single wavelength, GaborFilterGLTest). 0.15 bounds that.
  check_sliced_bake(s, 0.15);
}

// A band lasts about as long as the last frame, so the frames come at half rate and the tile is
// ready in about twice its bake whatever the per-pixel frames cost; within [slice, 4 x slice].
TEST(TileBakeBudget, ABandIsAsLongAsTheLastFrameWithinItsBounds) {
  EXPECT_EQ(slice_budget_ms(40.0, 0.0), 40.0);     // before the first frame: the slice
  EXPECT_EQ(slice_budget_ms(40.0, 12.0), 40.0);    // a fast frame: never below the slice
  EXPECT_EQ(slice_budget_ms(40.0, 105.0), 105.0);  // Table 4.1 c's per-pixel frame at 512^2
  EXPECT_EQ(slice_budget_ms(40.0, 900.0), kMaxSliceFactor * 40.0);  // a stalled frame: capped
}

PS_INSTANTIATE_HEADLESS_BACKENDS(TileBakeGLTest);

}  // namespace
}  // namespace ps
