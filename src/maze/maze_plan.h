// `maze plan` (docs/maze.md, "Planning a study"): participant IDs, seeds, conditions and
// counterbalanced cue-room orders for a study, as a CSV the experimenter keeps and `maze --plan`
// runs row by row. Room orders come from a balanced Latin square (Williams design) of the five
// cue rooms: 10 rows in which every room stands at every position twice and follows every other
// room twice. Participant i (from 0) takes rows i, i + 1, ... (mod 10) for passes 1, 2, ..., so
// the listed passes of every participant hold each row once, and first passes rotate through
// the rows. Conditions alternate (P01 the first, P02 the second, ...); every participant gets a
// seed of their own (the correct exits) and one row per session (retests keep seed and orders).
// No GL, no I/O besides the CSV.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/result.h"
#include "maze/maze.h"

namespace ps::maze {

using RoomOrder = std::array<Cue, 5>;  // the cue rooms of one pass, after the learning room

inline constexpr int kPlanPasses = 10;  // orders listed per participant: the square's 10 rows

struct PlanSpec {
  int participants = 12;
  std::vector<bool> conditions{true, false};  // cues on / off, alternated
  std::uint64_t first_seed = 101;             // participant i gets first_seed + i
  int sessions = 2;                           // 1 + retests
};

struct PlanRow {
  std::string participant;  // P01, P02, ... (P001 past 99)
  int session = 1;
  bool cues = true;
  std::uint64_t seed = 0;
  std::vector<RoomOrder> orders;  // pass 1, 2, ...
};

// A balanced Latin square (Williams 1949) of n treatments 0 .. n-1: the first row 0, 1, n-1, 2,
// n-2, ... and its n cyclic shifts; for odd n those rows again, each reversed (2n rows). Every
// treatment stands at every position equally often and follows every other one equally often.
// Shared by the maze's room orders and `study plan`'s condition orders (docs/study.md).
std::vector<std::vector<int>> williams_square(int n);
// The Williams square of the five cue rooms (10 rows).
std::vector<RoomOrder> williams_orders();
std::vector<PlanRow> make_plan(const PlanSpec& spec);
std::string plan_csv(const std::vector<PlanRow>& rows);
// Reads a plan CSV; errors name file:line.
Result<std::vector<PlanRow>> read_plan(const std::string& path);
// The row of `participant` in `session`; an error naming the plan when there is none.
Result<PlanRow> find_plan_row(const std::vector<PlanRow>& rows, const std::string& participant, int session,
                              const std::string& plan_path);

// read_plan + find_plan_row.
Result<PlanRow> load_plan_row(const std::string& plan_path, const std::string& participant, int session);

std::string order_text(const RoomOrder& order);  // "texture viscosity elastic hidden_sphere external_force"

}  // namespace ps::maze
