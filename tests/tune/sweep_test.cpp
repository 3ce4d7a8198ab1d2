// Sweep specs, cell enumeration, labels and override files (no GL).
#include <gtest/gtest.h>

#include <filesystem>

#include "core/file_io.h"
#include "tune/overrides_file.h"
#include "tune/sweep.h"
#include "tune/sweep_shard.h"

namespace ps {
namespace {

TEST(SweepTest, ListAndRangeValues) {
  auto list = parse_sweep("materials.wood.lambda_min=0.2,0.4, 0.8");
  ASSERT_TRUE(list) << list.error().message;
  EXPECT_EQ(list->key, "materials.wood.lambda_min");
  EXPECT_EQ(list->values, (std::vector<std::string>{"0.2", "0.4", "0.8"}));
  auto range = parse_sweep("probe.radius_mm=2:10:5");
  ASSERT_TRUE(range) << range.error().message;
  EXPECT_EQ(range->values, (std::vector<std::string>{"2", "4", "6", "8", "10"}));
  auto arrays = parse_sweep("probe.velocity=[0,0,0],[150,0,0]");
  ASSERT_TRUE(arrays);
  EXPECT_EQ(arrays->values, (std::vector<std::string>{"[0,0,0]", "[150,0,0]"}));
}

TEST(SweepTest, BadSpecsNameTheProblem) {
  auto expect = [](const char* spec, const char* needle) {
    auto r = parse_sweep(spec);
    ASSERT_FALSE(r) << spec;
    EXPECT_NE(r.error().message.find(needle), std::string::npos) << r.error().message;
  };
  expect("probe.radius_mm", "expected KEY=V1,V2");
  expect("probe.radius_mm=1:2:1", "STEPS must be a whole number in [2, 256]");
  expect("probe.radius_mm=1:2:x", "STEPS must be a whole number");
  expect("probe.radius_mm=a:2:3", "FROM 'a' is not a number");
  expect("probe.radius_mm=1:nan:3", "TO must be finite");
  expect("probe.radius_mm=1,,2", "empty value");
  expect("probe.radius_mm=1,nan", "must be finite");
}

TEST(SweepTest, CellsRowMajorAndLimit) {
  std::vector<SweepAxis> axes{{"a.x", {"1", "2"}}, {"materials.m.b", {"3", "4", "5"}}};
  ASSERT_EQ(sweep_cell_count(axes).value(), 6u);
  EXPECT_EQ(sweep_cell(axes, 4), (std::vector<std::size_t>{1, 1}));
  EXPECT_EQ(sweep_label(axes, {1, 2}), "a.x=2 materials.m.b=5");  // keys as given; no unit known
  EXPECT_EQ(sweep_label({{"probe.velocity", {"[500,0,0]"}}, {"probe.radius_mm", {"2"}}}, {0, 0}),
            "probe.velocity=[500,0,0] mm/s probe.radius_mm=2 mm");
  std::vector<SweepAxis> big{{"a.x", std::vector<std::string>(17, "1")}, {"a.y", std::vector<std::string>(16, "1")}};
  auto n = sweep_cell_count(big);
  ASSERT_FALSE(n);
  EXPECT_NE(n.error().message.find("more than 256 cells (17 x 16)"), std::string::npos) << n.error().message;
  std::vector<SweepAxis> scenes{parse_scene_sweep("scenes/table4_1_a.toml,x/b.toml").value()};
  EXPECT_EQ(sweep_label(scenes, {0}), "table4_1_a");
}

TEST(OverridesFileTest, RoundTripAndQuoting) {
  std::map<std::string, std::string> edits{{"render.displacement", "exact_max"},
                                           {"materials.wood.lambda_min", "0.4"},
                                           {"probe.position", "[0,0,5]"}};
  const std::string text = format_overrides(edits, "s.toml");
  EXPECT_NE(text.find("render.displacement = \"exact_max\"\n"), std::string::npos) << text;
  const std::string path = testing::TempDir() + "/roundtrip.overrides.toml";
  ASSERT_TRUE(write_file_atomic(path, text));
  auto lines = read_overrides(path);
  ASSERT_TRUE(lines) << lines.error().message;
  EXPECT_EQ(lines.value(), (std::vector<std::string>{"materials.wood.lambda_min=0.4", "probe.position=[0,0,5]",
                                                     "render.displacement=\"exact_max\""}));
  EXPECT_EQ(overrides_path_for("scenes/a.toml"), "scenes/a.overrides.toml");
}

// A relative file value inside an override file resolves against that file's directory, not the
// working directory nor the scene's (docs/scene-format.md "Paths").
TEST(OverridesFileTest, RelativeFileResolvesAgainstTheOverrideFile) {
  const std::filesystem::path dir = std::filesystem::absolute(testing::TempDir()) / "anchored";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "a.overrides.toml").string();
  ASSERT_TRUE(write_file_atomic(path, "materials.wood.intensity_lut = \"a.wood.intensity.lut\"\nprobe.radius_mm = 3\n"));
  auto lines = read_overrides(path);
  ASSERT_TRUE(lines) << lines.error().message;
  const std::string lut = (dir / "a.wood.intensity.lut").lexically_normal().string();
  EXPECT_EQ(lines.value(), (std::vector<std::string>{"materials.wood.intensity_lut=\"" + lut + "\"",
                                                     "probe.radius_mm=3"}));
}

TEST(OverridesFileTest, MalformedLineNamesFileAndLine) {
  const std::string path = testing::TempDir() + "/bad.overrides.toml";
  ASSERT_TRUE(write_file_atomic(path, "# ok\nprobe.radius_mm = 3\nnonsense\n"));
  auto lines = read_overrides(path);
  ASSERT_FALSE(lines);
  EXPECT_NE(lines.error().message.find("bad.overrides.toml:3: expected KEY = VALUE"), std::string::npos);
}

}  // namespace
// --shard I/N: the N shards partition the cells, each cell in exactly one, round robin (so a
// shard of a 2-axis sweep holds values of every axis); bad specs name the problem.
TEST(ShardTest, ShardsPartitionTheCellsRoundRobin) {
  for (std::size_t n : {1u, 2u, 3u, 7u, 12u}) {
    std::vector<int> owners(12, 0);
    for (std::size_t i = 1; i <= n; ++i) {
      auto s = parse_shard(std::to_string(i) + "/" + std::to_string(n));
      ASSERT_TRUE(s) << s.error().message;
      for (std::size_t c = 0; c < owners.size(); ++c) owners[c] += s->contains(c);
    }
    for (std::size_t c = 0; c < owners.size(); ++c) EXPECT_EQ(owners[c], 1) << "cell " << c << " of " << n << " shards";
  }
  auto two = parse_shard("2/3");
  ASSERT_TRUE(two);
  EXPECT_TRUE(two->contains(1));
  EXPECT_TRUE(two->contains(4));
  EXPECT_FALSE(two->contains(2));
  EXPECT_EQ(parse_shard("0/3").error().message, "--shard 0/3: I must be in [1, N]");
  EXPECT_EQ(parse_shard("4/3").error().message, "--shard 4/3: I must be in [1, N]");
  EXPECT_EQ(parse_shard("1/0").error().message, "--shard 1/0: N must be in [1, 256]");
  EXPECT_EQ(parse_shard("2").error().message, "--shard 2: expected I/N, shard I of N (e.g. 2/8)");
  EXPECT_EQ(parse_shard("a/b").error().message, "--shard a/b: expected I/N, shard I of N (e.g. 2/8)");
}

}  // namespace ps
