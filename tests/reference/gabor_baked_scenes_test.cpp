// Strategy "auto" on every textured material the project ships, against the outcome measured
// for it (kExpected): a baked tile (which one), or the naive sum because no tile meets the bar
// or none is long enough. Each outcome's reason is checked independently of the one
// choose_gabor_tile() made: the error on another 50 x 50 set of points with other offsets (the
// same CPU twins in double, so this is the method's error, not float rounding), the period
// bound from the tile's definition. The numbers are printed for docs/benchmarks.md.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "reference/gabor.h"
#include "reference/probe_geometry.h"
#include "scene/scene_io.h"

namespace ps {
namespace {

// RMS of (baked - naive) / sigma over 50 x 50 points of the central period (away from its edge
// by one cell: the periodic texture equals the naive one only there).
double independent_rms(const GaborParams& g, const GaborSetup& s, const GaborBakePlan& plan, std::uint32_t seed) {
  const double side = std::min(40.0, plan.period_mm - 2.0 * s.cell_mm);
  double sum2 = 0.0;
  constexpr int kN = 50;
  for (int j = 0; j < kN; ++j)
    for (int i = 0; i < kN; ++i) {
      const double u = side * ((i + 0.71) / kN - 0.5), v = side * ((j + 0.13) / kN - 0.5);
      const double e = (gabor_noise_baked(g, s, plan, seed, u, v) - gabor_noise(g, s, seed, u, v)) / s.sigma_unit;
      sum2 += e * e;
    }
  return std::sqrt(sum2 / (kN * kN));
}

// What "auto" must do with each shipped scene's material, measured (docs/benchmarks.md) and
// written down here, so a change of the selection shows as a changed outcome rather than a
// restatement of the selection's own conditions. The outcomes near the bar depend on the
// texture drawn: with the cell seeds of issue 30 (every cell its own), table4_1_a, table4_1_d
// and monkey_head measure 0.88 %, 0.79 % and 0.90 % on the selection's points and are baked
// (with the former seeds no tile of theirs came within 0.9 %).
enum class Outcome {
  kBaked,        // a tile: `linear` and `samples` name which one (the first try that passes)
  kNaiveError,   // every tile long enough misses the 0.9 % bar
  kNaivePeriod,  // no tile's period reaches the shadow's width
};
struct Expected {
  const char* scene;
  Outcome outcome;
  bool linear = false;
  int samples = 0;  // per lambda_min
};
// The tries of "auto", in order (reference/gabor.h): bilinear 24, 32; Hermite 16, 32.
struct Try {
  bool linear;
  int samples;
};
constexpr Try kTries[] = {{true, 24}, {true, 32}, {false, 16}, {false, 32}};

const Expected kExpected[] = {
    {"default.toml", Outcome::kBaked, true, 24},
    {"fields_bodies_demo.toml", Outcome::kBaked, true, 24},  // the default scene's wood and probe
    {"heightfield.toml", Outcome::kBaked, true, 32},
    {"table4_1_a.toml", Outcome::kBaked, false, 32},
    {"table4_1_b.toml", Outcome::kBaked, true, 24},
    {"table4_1_c.toml", Outcome::kBaked, false, 16},
    {"table4_1_d.toml", Outcome::kBaked, true, 32},
    {"table4_1_e.toml", Outcome::kNaiveError},
    {"table4_1_f.toml", Outcome::kNaiveError},
    {"table5_1_construction_paper.toml", Outcome::kBaked, true, 24},
    {"table5_1_monkey_head.toml", Outcome::kBaked, false, 32},
    {"table5_1_sandpaper.toml", Outcome::kBaked, true, 32},
    // lambda_min 0.1 mm: a 2048-texel tile at 16 samples holds 12.8 mm, the shadow is 16 mm.
    {"table5_1_wood.toml", Outcome::kNaivePeriod},
    // Capsule r 6 mm, 40 mm long: a 52 mm shadow; lambda_min 0.4 mm gives at most 51.2 mm.
    {"torus_capsule.toml", Outcome::kNaivePeriod},
};

const Expected* expected_for(const std::string& scene_file) {
  for (const Expected& e : kExpected)
    if (scene_file == e.scene) return &e;
  return nullptr;
}

GaborBakePlan plan_for(const GaborParams& g, const GaborSetup& s, Try t) {
  GaborParams tried = g;
  tried.bake_samples_per_lambda = t.samples;
  GaborBakePlan plan = make_gabor_bake_plan(tried, s);
  plan.linear = t.linear;
  return plan;
}

// The longest period any tile of "auto" can have, from the definition (reference/gabor.h):
// at most kMaxBakeTexels texels of at most lambda_min / samples each, and the fewest samples
// tried is 16. Independent of make_gabor_bake_plan()'s rounding to whole, even cells.
double longest_possible_period_mm(const GaborParams& g) {
  return kMaxBakeTexels * std::min(g.lambda_min_mm, g.lambda_max_mm) / 16.0;
}

void check_material(const std::string& file, const Scene& scene, Material m, const Expected& want,
                    int& baked) {
  const std::uint32_t seed = scene.render.seed;
  m.gabor.strategy = GaborParams::Strategy::kAuto;
  const GaborSetup s = make_gabor_setup(m.gabor);
  // The renderer's minimum period: the shadow window, 2 x the probe's bounding radius (every
  // shipped scene's probe is analytic, so no mesh is needed for its bounds).
  ASSERT_NE(scene.probe.shape, ProbeShape::kMesh) << file;
  const double window = 2.0 * probe_bounds(scene.probe).radius;
  const GaborStrategyChoice c = choose_gabor_tile(m.gabor, s, seed, window);
  switch (want.outcome) {
    case Outcome::kNaivePeriod: {
      std::printf("%-34s naive: longest possible period %.1f mm < shadow %.1f mm\n", file.c_str(),
                  longest_possible_period_mm(m.gabor), window);
      EXPECT_FALSE(c.plan.ok) << file << ": no tile can be long enough, yet one was chosen";
      EXPECT_LT(longest_possible_period_mm(m.gabor), window) << file << ": the stated reason no longer holds";
      break;
    }
    case Outcome::kNaiveError: {
      EXPECT_FALSE(c.plan.ok) << file << ": expected the naive sum, got a tile of period " << c.plan.period_mm;
      // The reason, on this test's own 2500 points: the tiles long enough are near or over the
      // bar, not far inside it. The selection refused them on estimates > 0.9 % from its 4096
      // points; estimates scatter by 10-20 % between point sets, and here they measure 1.23 %
      // and 1.24 % (table4_1_e, _f: Hermite 16, the only tile long enough). A tile refused while it measures below 0.6 % would
      // be a selection that refuses good tiles.
      double best = 1e30;
      for (const Try t : kTries) {
        const GaborBakePlan plan = plan_for(m.gabor, s, t);
        if (!plan.ok || plan.period_mm < window) continue;
        const double rms = independent_rms(m.gabor, s, plan, seed);
        std::printf("%-34s naive: %s %d tile RMS %.4f sigma\n", file.c_str(), t.linear ? "bilinear" : "Hermite",
                    t.samples, rms);
        best = std::min(best, rms);
      }
      EXPECT_LT(best, 1e30) << file << ": no tile is long enough, so the reason is the period";
      EXPECT_GT(best, 0.006) << file << ": a tile far within the bar was refused";
      break;
    }
    case Outcome::kBaked: {
      ASSERT_TRUE(c.plan.ok) << file << ": expected a tile, got the naive sum (estimate " << c.rms_vs_naive << ")";
      const Try* chosen = nullptr;
      for (const Try& t : kTries) {
        const GaborBakePlan p = plan_for(m.gabor, s, t);
        if (p.ok && p.linear == c.plan.linear && p.texels == c.plan.texels && p.period_cells == c.plan.period_cells) {
          chosen = &t;
          break;
        }
      }
      ASSERT_NE(chosen, nullptr) << file << ": the chosen tile is none of the tries";
      EXPECT_EQ(chosen->linear, want.linear) << file;
      EXPECT_EQ(chosen->samples, want.samples) << file;
      const double rms = independent_rms(m.gabor, s, c.plan, seed);
      std::printf("%-34s tile %s %d: %4d^2, period %5.1f mm (%d cells), shadow %.1f mm, RMS vs naive %.4f "
                  "sigma (chosen on %.4f)\n",
                  file.c_str(), chosen->linear ? "bilinear" : "Hermite", chosen->samples, c.plan.texels,
                  c.plan.period_mm, c.plan.period_cells, window, rms, c.rms_vs_naive);
      EXPECT_LE(c.plan.texels, kMaxBakeTexels);
      EXPECT_GE(c.plan.period_mm, window);
      // The selection asked for <= 0.9 % on its 4096 points (kAutoBakeSelectRms); another set of
      // 2500 points scatters by ~10-20 % around that for sparse textures, so 1.1 % here. A
      // systematic miss (a wrong plan, a wrapped cell inside the central period, a lookup that
      // disagrees with the bake) shows as several percent.
      EXPECT_LT(rms, 0.011) << file;
      ++baked;
      break;
    }
  }
}

TEST(GaborBakedScenesTest, AutoChoosesTheMeasuredTileForEveryShippedMaterial) {
  int baked = 0, textured = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(PS_SOURCE_DIR) + "/scenes")) {
    if (entry.path().extension() != ".toml") continue;
    const std::string file = entry.path().filename().string();
    // The materials demo draws five materials from the library scenes/materials/
    // virtual_universe.toml; kExpected holds one material per scene, and the library's
    // outcomes are not measured yet.
    if (file == "materials_demo.toml") continue;
    auto scene = load_scene(entry.path().string(), {});
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    for (const Material& m : scene->materials) {
      if (!m.textured) continue;
      ++textured;
      const Expected* want = expected_for(file);
      ASSERT_NE(want, nullptr) << file << " is not in kExpected: measure it and add it";
      ASSERT_EQ(scene->materials.size(), 1u) << file << ": kExpected holds one material per scene";
      check_material(file, *scene, m, *want, baked);
    }
  }
  std::printf("%d of %d textured materials baked\n", baked, textured);
  EXPECT_EQ(textured, static_cast<int>(std::size(kExpected)));
  EXPECT_EQ(baked, 10);  // docs/benchmarks.md (nine scenes, and the fields demo on the default wood)
}

}  // namespace
}  // namespace ps
