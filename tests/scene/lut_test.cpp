// Lookup tables (scene/lut.h): the format, its errors (file:line), linear interpolation with
// clamped ends, the written text reading back, and the two material keys.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "reference/modulation.h"
#include "scene/lut.h"
#include "scene_test_util.h"

namespace ps {
namespace {

std::string lut_error(const std::string& text) {
  auto lut = parse_lut(text, "t.lut");
  return lut ? std::string("<ok>") : lut.error().message;
}

std::string write_temp(const std::string& name, const std::string& text) {
  // Normalised as the scene reader normalises a file key's path (messages name it so).
  const std::string path = (std::filesystem::path(::testing::TempDir()) / name).lexically_normal().string();
  std::ofstream(path) << text;
  return path;
}

TEST(LutTest, ParsesHeaderRowsCommentsAndCommas) {
  auto lut = parse_lut("# a comment\n\nlut speed_mm_s gain  # trailing comment\n0 0.5\n100, 1\n\n250\t0.25\n",
                       "t.lut");
  ASSERT_TRUE(lut.ok()) << lut.error().message;
  EXPECT_EQ(lut->axis, LutAxis::kSpeedMmS);
  ASSERT_EQ(lut->points.size(), 3u);
  EXPECT_EQ(lut->points[1], (LutPoint{100.0, 1.0}));
  EXPECT_EQ(lut->points[2], (LutPoint{250.0, 0.25}));
}

TEST(LutTest, MalformedTablesNameFileAndLine) {
  EXPECT_EQ(lut_error(""), "t.lut:1: empty lookup table (e.g. `lut distance_mm intensity` then rows like `0.5 0.55`)");
  EXPECT_EQ(lut_error("# c\nlut distance_mm brightness\n"),
            "t.lut:2: expected the header `lut distance_mm intensity` or `lut speed_mm_s gain`, got "
            "'lut distance_mm brightness'");
  EXPECT_EQ(lut_error("lut distance_mm intensity\n0 1\n1 x\n"),
            "t.lut:3: expected a row of two finite numbers `x y`, got '1 x' (e.g. `lut distance_mm intensity` "
            "then rows like `0.5 0.55`)");
  EXPECT_EQ(lut_error("lut distance_mm intensity\n0 1\n1 0.5 2\n").rfind("t.lut:3: expected a row", 0), 0u);
  EXPECT_EQ(lut_error("lut distance_mm intensity\n0 1\n1 nan\n").rfind("t.lut:3: expected a row", 0), 0u);
  EXPECT_EQ(lut_error("lut distance_mm intensity\n-1 1\n1 0.5\n"), "t.lut:2: distance_mm -1 must be >= 0");
  EXPECT_EQ(lut_error("lut distance_mm intensity\n0 1\n1 1.5\n"), "t.lut:3: intensity 1.5 must be in [0, 1]");
  EXPECT_EQ(lut_error("lut speed_mm_s gain\n0 1\n2 0.5\n\n2 0.4\n"),
            "t.lut:5: speed_mm_s 2 must be greater than the previous row's 2 (rows in increasing x)");
  EXPECT_EQ(lut_error("lut distance_mm intensity\n\n0 1\n"), "t.lut:3: a lookup table needs at least 2 rows, got 1");
  std::string many = "lut distance_mm intensity\n";
  for (int i = 0; i <= kMaxLutRows; ++i) many += std::to_string(i) + " 0.5\n";
  EXPECT_EQ(lut_error(many), "t.lut:258: more than 256 rows");
}

TEST(LutTest, LinearBetweenRowsClampedOutside) {
  Lut lut;
  lut.points = {{1.0, 0.8}, {3.0, 0.4}, {4.0, 0.4}, {8.0, 0.0}};
  EXPECT_EQ(lut_eval(lut, 0.0), 0.8);  // before the first row: its value
  EXPECT_EQ(lut_eval(lut, 1.0), 0.8);
  EXPECT_NEAR(lut_eval(lut, 2.0), 0.6, 1e-15);  // halfway: double rounding only
  EXPECT_NEAR(lut_eval(lut, 2.5), 0.5, 1e-15);
  EXPECT_EQ(lut_eval(lut, 3.0), 0.4);  // a row exactly
  EXPECT_EQ(lut_eval(lut, 3.7), 0.4);
  EXPECT_NEAR(lut_eval(lut, 7.0), 0.1, 1e-15);
  EXPECT_EQ(lut_eval(lut, 8.0), 0.0);
  EXPECT_EQ(lut_eval(lut, 1e9), 0.0);  // after the last row: its value
}

TEST(LutTest, HugeFileIsRefusedBeforeReading) {
  const std::string path = write_temp("huge.lut", "lut distance_mm intensity\n" + std::string(1 << 20, '#'));
  auto lut = read_lut(path, LutAxis::kDistanceMm);
  ASSERT_FALSE(lut.ok());
  EXPECT_EQ(lut.error().message, path + ": lookup table file is 1048602 bytes, more than the limit of 1048576");
}

TEST(LutTest, WrittenTextReadsBack) {
  Lut lut;
  lut.axis = LutAxis::kSpeedMmS;
  lut.points = {{0.0, 0.1}, {1.0 / 3.0, 2.0 / 3.0}, {123.456789, 1.0}};
  const std::string path = ::testing::TempDir() + "/round_trip.lut";
  ASSERT_TRUE(write_lut(path, lut, {"made by a test"}).ok());
  auto back = read_lut(path, LutAxis::kSpeedMmS);
  ASSERT_TRUE(back.ok()) << back.error().message;
  ASSERT_EQ(back->points.size(), lut.points.size());
  // 9 significant digits (format_lut): the relative error of a row is below 5e-9.
  for (std::size_t i = 0; i < lut.points.size(); ++i) {
    EXPECT_NEAR(back->points[i].x, lut.points[i].x, 5e-9 * std::abs(lut.points[i].x));
    EXPECT_NEAR(back->points[i].y, lut.points[i].y, 5e-9 * std::abs(lut.points[i].y));
  }
  EXPECT_EQ(back->file, path);
}

// A scene whose material `wood` (line 1) has `lines` from line 3 on.
std::string scene_with(const std::string& lines) {
  return "[materials.wood]\nlambda_min = 0.1\n" + lines + "[[surfaces]]\nmaterial = \"wood\"\n";
}

TEST(LutTest, MaterialKeysLoadTablesAndCheckTheirAxis) {
  const std::string speed = write_temp("speed.lut", "lut speed_mm_s gain\n0 0.2\n100 1\n");
  // The temporary folder is outside the scene's: allowed as a user would (scene/path_policy.h).
  auto s = parse_scene(scene_with("intensity_lut = \"../textures/intensity_thesis.lut\"\n"
                                  "[materials.stone]\nspeed_gain_lut = \"" + speed + "\"\n"),
                       "s.toml", test::scenes_dir(), {}, {std::filesystem::path(speed).parent_path().string()});
  ASSERT_TRUE(s.ok()) << s.error().message;
  const Material& wood = s->materials[0].name == "wood" ? s->materials[0] : s->materials[1];
  const Material& stone = s->materials[0].name == "stone" ? s->materials[0] : s->materials[1];
  EXPECT_EQ(wood.intensity_lut.points.size(), 21u);
  EXPECT_TRUE(wood.speed_gain_lut.empty());
  EXPECT_TRUE(stone.intensity_lut.empty());
  EXPECT_NEAR(amplitude_gain(stone, 50.0), 0.6, 1e-15);
  EXPECT_NEAR(amplitude_gain(stone, 500.0), 1.0, 0.0);

  // The shipped thesis table lies on the thesis curve at its rows and within 0.006 between
  // them (the linear segments' largest sag, 0.0055 between 0 and 0.25 mm, where it bends most).
  Material formula = wood;
  formula.intensity_lut = {};
  double worst = 0.0;
  for (double d = 0.001; d < 50.0; d += 0.001)
    worst = std::max(worst, std::abs(shadow_intensity(wood, d) - shadow_intensity(formula, d)));
  EXPECT_LT(worst, 0.006);
  for (const LutPoint& p : wood.intensity_lut.points)
    if (p.x > 0.0) {
      EXPECT_NEAR(shadow_intensity(wood, p.x), shadow_intensity(formula, p.x), 5e-9);
    }

  // The wrong kind of table, a broken table, a missing file: the table's file:line, or the key's.
  const std::string bad = write_temp("bad.lut", "lut distance_mm intensity\n0 1\n0.5 2\n");
  const std::vector<std::string> allow = {std::filesystem::path(speed).parent_path().string()};
  auto error_of = [&](const std::string& text) {
    auto r = parse_scene(text, "s.toml", test::scenes_dir(), {}, allow);
    return r ? std::string("<ok>") : r.error().message;
  };
  EXPECT_EQ(error_of(scene_with("intensity_lut = \"" + speed + "\"\n")),
            speed + ":1: this key needs a `lut distance_mm intensity` table, the file is a `lut speed_mm_s gain` table");
  EXPECT_EQ(error_of(scene_with("intensity_lut = \"" + bad + "\"\n")),
            bad + ":3: intensity 2 must be in [0, 1]");
  const std::string e = test::error_of(scene_with("speed_gain_lut = \"nope.lut\"\n"));
  EXPECT_EQ(e.rfind("s.toml:3: 'speed_gain_lut' file not found: ", 0), 0u) << e;
}

// Beyond the influence distance there is no pseudo-shadow whatever the table says, and at
// contact the table is not read: 1 (thesis §4.3.2's jump).
TEST(LutTest, InfluenceDistanceAndContactStayTheCurves) {
  Material m;
  m.influence_distance_mm = 10.0;
  m.intensity_lut.points = {{0.0, 0.5}, {20.0, 0.5}};
  EXPECT_EQ(shadow_intensity(m, 9.999), 0.5);
  EXPECT_EQ(shadow_intensity(m, 10.0), 0.0);
  EXPECT_EQ(shadow_intensity(m, 15.0), 0.0);
  EXPECT_EQ(shadow_intensity(m, 0.0), 1.0);
  EXPECT_EQ(shadow_intensity(m, -1.0), 1.0);
  EXPECT_EQ(shadow_intensity(m, std::nan("")), 0.0);
}

}  // namespace
}  // namespace ps
