// `maze plan`: the Williams square of the five cue rooms and the plans built from it. Every
// count below is exact (integers).
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <set>

#include "maze/maze_plan.h"
#include "maze_test_util.h"

namespace ps::maze {
namespace {

// [room][position] counts over the given orders.
std::array<std::array<int, 5>, 6> position_counts(const std::vector<RoomOrder>& orders) {
  std::array<std::array<int, 5>, 6> n{};
  for (const RoomOrder& o : orders)
    for (std::size_t k = 0; k < 5; ++k) ++n[static_cast<std::size_t>(o[k])][k];
  return n;
}

TEST(MazePlanTest, WilliamsSquareBalancesPositionsAndNeighbours) {
  const auto rows = williams_orders();
  ASSERT_EQ(rows.size(), 10u);
  for (const RoomOrder& r : rows) EXPECT_EQ(std::set<Cue>(r.begin(), r.end()).size(), 5u) << order_text(r);
  const auto n = position_counts(rows);
  for (const Cue c : kCueRooms)
    for (std::size_t k = 0; k < 5; ++k) EXPECT_EQ(n[static_cast<std::size_t>(c)][k], 2) << cue_name(c) << " at " << k;
  // First-order carry-over: every room directly follows every other room equally often (twice:
  // 20 ordered pairs over 10 rows x 4 neighbours).
  std::map<std::pair<Cue, Cue>, int> follows;
  for (const RoomOrder& r : rows)
    for (std::size_t k = 0; k + 1 < 5; ++k) ++follows[{r[k], r[k + 1]}];
  EXPECT_EQ(follows.size(), 20u);
  for (const auto& [pair, count] : follows) EXPECT_EQ(count, 2) << cue_name(pair.first) << " -> " << cue_name(pair.second);
}

TEST(MazePlanTest, EveryRoomAtEveryPositionEquallyOftenForSixAndTwelve) {
  for (const int participants : {6, 12}) {
    PlanSpec spec;
    spec.participants = participants;
    spec.sessions = 1;
    const auto plan = make_plan(spec);
    ASSERT_EQ(plan.size(), static_cast<std::size_t>(participants));
    std::vector<RoomOrder> all;
    std::set<std::uint64_t> seeds;
    int on = 0;
    for (const PlanRow& r : plan) {
      ASSERT_EQ(r.orders.size(), static_cast<std::size_t>(kPlanPasses));
      all.insert(all.end(), r.orders.begin(), r.orders.end());
      seeds.insert(r.seed);
      on += r.cues;
    }
    const auto n = position_counts(all);
    for (const Cue c : kCueRooms)
      for (std::size_t k = 0; k < 5; ++k)
        EXPECT_EQ(n[static_cast<std::size_t>(c)][k], 2 * participants) << participants << ": " << cue_name(c) << " at " << k;
    EXPECT_EQ(seeds.size(), static_cast<std::size_t>(participants)) << "a seed of their own";
    EXPECT_EQ(on, participants / 2) << "conditions alternate";
    EXPECT_TRUE(plan[0].cues);
    EXPECT_FALSE(plan[1].cues);
  }
}

// First passes rotate through the square's rows: ten participants' first passes are the ten rows.
TEST(MazePlanTest, FirstPassesOfTenParticipantsAreBalancedToo) {
  PlanSpec spec;
  spec.participants = 10;
  std::vector<RoomOrder> first;
  for (const PlanRow& r : make_plan(spec))
    if (r.session == 1) first.push_back(r.orders[0]);
  const auto n = position_counts(first);
  for (const Cue c : kCueRooms)
    for (std::size_t k = 0; k < 5; ++k) EXPECT_EQ(n[static_cast<std::size_t>(c)][k], 2) << cue_name(c) << " at " << k;
}

TEST(MazePlanTest, CsvRoundTripsAndBadRowsNameTheLine) {
  PlanSpec spec;
  spec.participants = 3;
  const auto plan = make_plan(spec);
  ASSERT_EQ(plan.size(), 6u);  // two sessions each: the retest keeps seed, condition and orders
  EXPECT_EQ(plan[1].participant, "P01");
  EXPECT_EQ(plan[1].session, 2);
  EXPECT_EQ(plan[1].seed, plan[0].seed);
  const std::string dir = test::temp_dir("plan");
  std::ofstream(dir + "/plan.csv") << plan_csv(plan);
  auto back = read_plan(dir + "/plan.csv");
  ASSERT_TRUE(back) << back.error().message;
  ASSERT_EQ(back->size(), plan.size());
  for (std::size_t i = 0; i < plan.size(); ++i) {
    EXPECT_EQ((*back)[i].participant, plan[i].participant);
    EXPECT_EQ((*back)[i].seed, plan[i].seed);
    EXPECT_EQ((*back)[i].cues, plan[i].cues);
    EXPECT_EQ((*back)[i].orders, plan[i].orders);
  }
  auto row = find_plan_row(back.value(), "P03", 1, "plan.csv");
  ASSERT_TRUE(row);
  EXPECT_EQ(row->seed, 103u);
  EXPECT_FALSE(find_plan_row(back.value(), "P09", 1, "plan.csv"));
  std::ofstream(dir + "/bad.csv") << "participant,session,condition,seed,order_pass_1\nP01,1,cues_on,5,texture texture elastic hidden_sphere external_force\n";
  auto bad = read_plan(dir + "/bad.csv");
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error().message.rfind(dir + "/bad.csv:2: not a plan row (room order", 0), 0u) << bad.error().message;
}

}  // namespace
}  // namespace ps::maze
