// The practice pass of `maze --practice` (docs/maze.md, "Practice") without the window: its
// options (another route, one pass, its own folder) and how such a pass ends. No GL.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "devices/sample_log.h"
#include "maze/maze.h"
#include "maze/maze_script.h"
#include "maze/maze_session.h"
#include "maze_test_util.h"

namespace ps::maze {
namespace {

// The practice pass (`maze --practice`) walked with a wrong exit: its one pass is all it has, so it
// ends by max_passes (not criterion), logged apart in DIR/practice/ on the practice's own route.
TEST(MazeSessionTest, PracticePassEndsByMaxPasses) {
  auto d = load_maze_desc(test::maze_file());
  ASSERT_TRUE(d) << d.error().message;
  const std::string dir = test::temp_dir("practice_max_passes");
  SessionOptions o;
  o.desc = d.value();
  o.route = draw_route(11);
  o.info.participant = "T";
  o.info.seed = o.route.seed;
  o.info.max_passes = d->max_passes;
  o.log_path = dir + "/session.jsonl";
  o.record_path = dir + "/device.log";
  auto po = practice_options(o);
  ASSERT_TRUE(po) << po.error().message;
  EXPECT_EQ(po->info.seed, o.info.seed ^ kPracticeSeedMix);
  EXPECT_EQ(po->desc.max_passes, 1);
  // A wrong exit in the practice's pass, then a perfect pass the session must never get to.
  const Route& route = po->route;
  std::ofstream(dir + "/p.traj") << script_trajectory(po->desc, {choices_with_errors(route, 0, 1), correct_choices(route, 1)}, 150.0);
  auto dev = open_log_device("trajectory:" + dir + "/p.traj");
  ASSERT_TRUE(dev) << dev.error().message;
  auto r = run_session(*dev.value(), po.value(), nullptr, nullptr);
  ASSERT_TRUE(r) << r.error().message;
  EXPECT_EQ(r->reason, EndReason::kMaxPasses);
  EXPECT_EQ(r->passes, 1);
  EXPECT_EQ(r->trials_to_criterion, 0);
  EXPECT_LT(r->ticks, static_cast<std::uint64_t>(dev.value()->duration_s() * 1000.0)) << "it stopped after its pass";
  const auto lines = test::read_lines(dir + "/practice/session.jsonl");
  ASSERT_FALSE(lines.empty());
  const auto start = nlohmann::json::parse(lines.front()), end = nlohmann::json::parse(lines.back());
  EXPECT_EQ(start.at("seed").get<std::uint64_t>(), po->info.seed);
  EXPECT_EQ(start.at("max_passes").get<int>(), 1);
  EXPECT_EQ(end.at("type"), "session_end");
  EXPECT_EQ(end.at("reason"), "max_passes");
  EXPECT_EQ(end.at("passes"), 1);
  EXPECT_TRUE(std::filesystem::exists(dir + "/practice/device.log"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/session.jsonl")) << "the session's own log is not the practice's";
}

}  // namespace
}  // namespace ps::maze
