#include "maze/maze_plan.h"

#include <cstdio>
#include <fstream>
#include <sstream>

namespace ps::maze {

std::vector<std::vector<int>> williams_square(int n) {
  std::vector<int> first;  // 0, 1, n-1, 2, n-2, ...
  for (int j = 0, lo = 1, hi = n - 1; j < n; ++j) first.push_back(j == 0 ? 0 : (j % 2 == 1 ? lo++ : hi--));
  std::vector<std::vector<int>> rows;
  for (int reversed = 0; reversed < (n % 2 == 1 ? 2 : 1); ++reversed)
    for (int shift = 0; shift < n; ++shift) {
      std::vector<int> r(static_cast<std::size_t>(n));
      for (int j = 0; j < n; ++j)
        r[static_cast<std::size_t>(reversed ? n - 1 - j : j)] = (first[static_cast<std::size_t>(j)] + shift) % n;
      rows.push_back(r);
    }
  return rows;
}

std::vector<RoomOrder> williams_orders() {
  std::vector<RoomOrder> rows;
  for (const std::vector<int>& w : williams_square(static_cast<int>(kCueRooms.size()))) {
    RoomOrder r{};
    for (std::size_t j = 0; j < r.size(); ++j) r[j] = kCueRooms[static_cast<std::size_t>(w[j])];
    rows.push_back(r);
  }
  return rows;
}

std::vector<PlanRow> make_plan(const PlanSpec& spec) {
  const std::vector<RoomOrder> square = williams_orders();
  std::vector<PlanRow> rows;
  for (int i = 0; i < spec.participants; ++i) {
    char id[16];
    std::snprintf(id, sizeof id, spec.participants > 99 ? "P%03d" : "P%02d", i + 1);
    PlanRow row;
    row.participant = id;
    row.cues = spec.conditions[static_cast<std::size_t>(i) % spec.conditions.size()];
    row.seed = spec.first_seed + static_cast<std::uint64_t>(i);
    for (int p = 0; p < kPlanPasses; ++p) row.orders.push_back(square[static_cast<std::size_t>((i + p) % kPlanPasses)]);
    for (int s = 1; s <= spec.sessions; ++s) {
      row.session = s;
      rows.push_back(row);
    }
  }
  return rows;
}

std::string order_text(const RoomOrder& order) {
  std::string t;
  for (const Cue c : order) t += (t.empty() ? "" : " ") + std::string(cue_name(c));
  return t;
}

std::string plan_csv(const std::vector<PlanRow>& rows) {
  std::ostringstream o;
  o << "participant,session,condition,seed";
  for (int p = 1; p <= kPlanPasses; ++p) o << ",order_pass_" << p;
  o << "\n";
  for (const PlanRow& r : rows) {
    o << r.participant << "," << r.session << "," << (r.cues ? "cues_on" : "cues_off") << "," << r.seed;
    for (const RoomOrder& order : r.orders) o << "," << order_text(order);
    o << "\n";
  }
  return o.str();
}

namespace {

std::vector<std::string> split(const std::string& line, char sep) {
  std::vector<std::string> out;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, sep)) out.push_back(cell);
  return out;
}

// One data line; throws the reason.
PlanRow read_row(const std::string& line) {
  const auto cells = split(line, ',');
  if (cells.size() < 5) throw std::runtime_error("expected participant,session,condition,seed and the room orders");
  PlanRow r;
  r.participant = cells[0];
  r.session = std::stoi(cells[1]);
  if (cells[2] != "cues_on" && cells[2] != "cues_off") throw std::runtime_error("condition must be cues_on or cues_off");
  r.cues = cells[2] == "cues_on";
  r.seed = std::stoull(cells[3]);
  for (std::size_t k = 4; k < cells.size(); ++k) {
    const auto names = split(cells[k], ' ');
    if (names.size() != 5) throw std::runtime_error("a room order names the five cue rooms, e.g. " + order_text(kCueRooms));
    RoomOrder order{};
    std::array<bool, 6> seen{};
    for (std::size_t j = 0; j < 5; ++j) {
      if (!parse_cue(names[j], order[j]) || order[j] == Cue::kNone || seen[static_cast<std::size_t>(order[j])])
        throw std::runtime_error("room order '" + cells[k] + "' must name each cue room once");
      seen[static_cast<std::size_t>(order[j])] = true;
    }
    r.orders.push_back(order);
  }
  return r;
}

}  // namespace

Result<std::vector<PlanRow>> read_plan(const std::string& path) {
  std::ifstream in(path);
  if (!in) return make_error(path + ": cannot open the plan (write one with `maze plan --participants N --out FILE`)");
  std::vector<PlanRow> rows;
  int n = 0;
  for (std::string line; std::getline(in, line);) {
    if (++n == 1 || line.empty()) continue;  // the header
    try {
      rows.push_back(read_row(line));
    } catch (const std::exception& e) {
      return make_error(path + ":" + std::to_string(n) + ": not a plan row (" + e.what() + ")");
    }
  }
  return rows;
}

Result<PlanRow> find_plan_row(const std::vector<PlanRow>& rows, const std::string& participant, int session,
                              const std::string& plan_path) {
  for (const PlanRow& r : rows)
    if (r.participant == participant && r.session == session) return r;
  return make_error(plan_path + ": no row for participant " + participant + ", session " + std::to_string(session) +
                    " (its first column lists the participants)");
}

Result<PlanRow> load_plan_row(const std::string& plan_path, const std::string& participant, int session) {
  auto rows = read_plan(plan_path);
  if (!rows) return rows.error();
  return find_plan_row(rows.value(), participant, session, plan_path);
}

}  // namespace ps::maze
