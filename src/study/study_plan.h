// `study plan` (docs/study.md, "Planning"): each participant's ID, seed and condition order. The
// orders are the rows of a balanced Latin square (maze::williams_square, the maze's own) of the
// experiment's conditions: participant i (from 0) takes row i mod the square's rows, so in every
// full round of rows each condition stands at each position equally often and follows every
// other equally often. `study run` computes the same row from the participant's ID, so a plan is
// what the experimenter keeps, never an input that could disagree with the run.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/result.h"
#include "study/experiment.h"

namespace ps::study {

struct PlanEntry {
  std::string participant;  // P01, P02, ... (P001 past 99)
  std::uint64_t seed = 0;   // first_seed + index
  std::vector<int> order;   // indices into Experiment::conditions
};

// "P07" -> 6; an error for any other form.
Result<int> participant_index(const std::string& id);
std::string participant_id(int index, int participants);  // 6 -> "P07" (P007 with over 99)
PlanEntry plan_entry(const Experiment& e, int index, int participants = 0);
std::vector<PlanEntry> make_study_plan(const Experiment& e, int participants);
// participant,seed,order (names separated by spaces),position_1..n
std::string study_plan_csv(const Experiment& e, const std::vector<PlanEntry>& plan);

}  // namespace ps::study
