#include "study/study_plan.h"

#include <cstdio>
#include <sstream>

#include "maze/maze_plan.h"

namespace ps::study {

Result<int> participant_index(const std::string& id) {
  const auto bad = [&] {
    return make_error("participant '" + id + "': IDs are P followed by a number from 1, as `study plan` writes them (P01, P02, ...)");
  };
  if (id.size() < 2 || id.size() > 7 || id[0] != 'P') return bad();
  for (std::size_t i = 1; i < id.size(); ++i)
    if (id[i] < '0' || id[i] > '9') return bad();
  const int n = std::stoi(id.substr(1));
  if (n < 1) return bad();
  return n - 1;
}

std::string participant_id(int index, int participants) {
  char id[16];
  std::snprintf(id, sizeof id, participants > 99 ? "P%03d" : "P%02d", index + 1);
  return id;
}

PlanEntry plan_entry(const Experiment& e, int index, int participants) {
  const auto square = maze::williams_square(static_cast<int>(e.conditions.size()));
  PlanEntry p;
  p.participant = participant_id(index, participants);
  p.seed = e.first_seed + static_cast<std::uint64_t>(index);
  p.order = square[static_cast<std::size_t>(index) % square.size()];
  return p;
}

std::vector<PlanEntry> make_study_plan(const Experiment& e, int participants) {
  std::vector<PlanEntry> plan;
  for (int i = 0; i < participants; ++i) plan.push_back(plan_entry(e, i, participants));
  return plan;
}

std::string study_plan_csv(const Experiment& e, const std::vector<PlanEntry>& plan) {
  std::ostringstream o;
  o << "participant,seed,order";
  for (std::size_t j = 1; j <= e.conditions.size(); ++j) o << ",position_" << j;
  o << "\n";
  for (const PlanEntry& p : plan) {
    std::string names;
    for (const int c : p.order) names += (names.empty() ? "" : " ") + e.conditions[static_cast<std::size_t>(c)].name;
    o << p.participant << "," << p.seed << "," << names;
    for (const int c : p.order) o << "," << e.conditions[static_cast<std::size_t>(c)].name;
    o << "\n";
  }
  return o.str();
}

}  // namespace ps::study
