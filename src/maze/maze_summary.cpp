#include "maze/maze_summary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "core/json_int.h"
#include "core/student_t.h"
#include "maze/maze_log.h"

namespace ps::maze {

namespace {

using nlohmann::json;

int cue_index(const json& j, const std::string& where) {
  Cue c = Cue::kNone;
  if (!j.is_string() || !parse_cue(j.get<std::string>(), c)) throw std::runtime_error(where + "unknown cue " + j.dump());
  return static_cast<int>(c);
}

void read_line(ParticipantSummary& p, const json& j, const std::string& where) {
  const std::string type = j.at("type").get<std::string>();
  if (j.contains("time_s")) p.total_time_s = std::max(p.total_time_s, j.at("time_s").get<double>());
  if (type == "session_start") {
    p.participant = j.at("participant").get<std::string>();
    p.session = json_int_or(j, "session", 1);
    p.condition = j.at("condition").get<std::string>();
    p.seed = json_int<std::uint64_t>(j.at("seed"), "seed");
    p.started_at = j.value("started_at", std::string());
    p.start_line = j.dump();
  } else if (type == "branch") {
    const auto c = static_cast<std::size_t>(cue_index(j.at("cue"), where));
    ++p.trials[c];
    if (!j.at("correct").get<bool>()) ++p.errors[c];
    p.room_time_s[c] += j.at("room_time_s").get<double>();
    RoomTrial r{json_int_or(j, "pass", 0), json_int_or(j, "room", 0), j.at("cue").get<std::string>(), j.value("exit", std::string()),
                j.at("correct").get<bool>(), j.at("room_time_s").get<double>(), j.value("path_mm", 0.0), {}};
    if (j.contains("contacts"))
      for (int k = 0; k < 4; ++k)
        r.contacts[static_cast<std::size_t>(k)] = json_int_or(j.at("contacts"), surface_kind_name(static_cast<SurfaceKind>(k)), 0);
    p.rooms.push_back(std::move(r));
  } else if (type == "pass_end") {
    ++p.passes;
    p.pass_time_s.push_back(j.at("pass_time_s").get<double>());
    p.pass_correct.push_back(json_int<int>(j.at("correct"), "correct"));
  } else if (type == "resumed") {  // one session, interrupted: what follows continues it
    ++p.resumed;
    p.ended = false;
  } else if (type == "session_end") {
    p.ended = true;
    if (!j.at("reason").is_string() || !parse_end_reason(j.at("reason").get<std::string>(), p.end_reason))
      throw std::runtime_error("unknown session_end reason " + j.at("reason").dump());
    p.trials_to_criterion = j.at("trials_to_criterion").is_null() ? 0 : json_int<int>(j.at("trials_to_criterion"), "trials_to_criterion");
  }
}

// A folder's session logs (find_session_logs): its own, else each subfolder's, in name order.
std::vector<std::string> logs_in_folder(const std::filesystem::path& dir) {
  if (std::filesystem::is_regular_file(dir / "session.jsonl")) return {(dir / "session.jsonl").string()};
  std::vector<std::string> logs;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
    if (entry.is_directory() && std::filesystem::is_regular_file(entry.path() / "session.jsonl"))
      logs.push_back((entry.path() / "session.jsonl").string());
  std::sort(logs.begin(), logs.end());
  return logs;
}

}  // namespace

double ParticipantSummary::mean_room_time_s(int cue) const {
  const auto c = static_cast<std::size_t>(cue);
  return trials[c] > 0 ? room_time_s[c] / trials[c] : std::nan("");
}

Result<std::vector<std::string>> find_session_logs(const std::vector<std::string>& args, std::vector<std::string>& notes) {
  std::vector<std::string> logs;
  for (const std::string& arg : args) {
    std::error_code ec;
    if (!std::filesystem::is_directory(arg, ec)) {
      if (!std::filesystem::exists(arg, ec))
        return make_error(arg + ": no such file or folder (give session logs, participants' folders or a study folder)");
      logs.push_back(arg);
      continue;
    }
    const std::vector<std::string> found = logs_in_folder(arg);
    if (found.empty()) notes.push_back(arg + ": no session.jsonl in it or in its subfolders: nothing from it");
    logs.insert(logs.end(), found.begin(), found.end());
  }
  return logs;
}

Result<ParticipantSummary> summarize_log(const std::string& path) {
  ParticipantSummary p;
  p.log = path;
  auto n = read_session_log(path, "give the session.jsonl a `maze` run wrote, or its folder", "",
                            [&](const json& j, const std::string& where) { read_line(p, j, where); }, &p.torn);
  if (!n) return n.error();
  return p;
}

namespace {

// Two logs of one run: the same participant, session and start (started_at, or for logs written
// before that field the same session_start line).
bool same_run(const ParticipantSummary& a, const ParticipantSummary& b) {
  if (a.participant != b.participant || a.session != b.session) return false;
  return a.started_at.empty() || b.started_at.empty() ? a.start_line == b.start_line : a.started_at == b.started_at;
}

}  // namespace

Status check_no_duplicates(const std::vector<ParticipantSummary>& people) {
  for (std::size_t i = 0; i < people.size(); ++i)
    for (std::size_t k = 0; k < i; ++k) {
      const ParticipantSummary &a = people[k], &b = people[i];
      if (!same_run(a, b)) continue;
      return make_error(a.log + " and " + b.log + " are the same session (participant " + a.participant + ", session " +
                        std::to_string(a.session) +
                        (a.started_at.empty() ? ", the same session_start line" : ", started " + a.started_at) +
                        "): give each session once");
    }
  return ok_status();
}

namespace {

// Student's t at 0.975 for df degrees of freedom: the two-sided 95 % interval's factor, exact
// (core/student_t.h; a 3-decimal table with 1.96 past 30 degrees of freedom before, which made
// intervals of more than 31 participants up to 4 % too narrow).
double t975(int df) { return student_t_quantile(0.975, df); }

GroupSummary& group_of(std::vector<GroupSummary>& groups, const ParticipantSummary& p) {
  auto it = std::find_if(groups.begin(), groups.end(),
                         [&](const GroupSummary& g) { return g.condition == p.condition && g.session == p.session; });
  if (it != groups.end()) return *it;
  GroupSummary g;
  g.condition = p.condition;
  g.session = p.session;
  return groups.emplace_back(std::move(g));
}

void fill_group(GroupSummary& g, const std::vector<const ParticipantSummary*>& members) {
  g.participants = static_cast<int>(members.size());
  std::vector<double> ttc, total;
  std::array<std::vector<double>, kCueCount> errors, room_time;
  std::vector<std::vector<double>> pass_time;
  for (const ParticipantSummary* p : members) {
    if (p->trials_to_criterion > 0) ttc.push_back(p->trials_to_criterion);
    total.push_back(p->total_time_s);
    for (std::size_t c = 0; c < kCueCount; ++c) {
      errors[c].push_back(p->errors[c]);
      if (p->trials[c] > 0) room_time[c].push_back(p->mean_room_time_s(static_cast<int>(c)));  // left that room
    }
    for (std::size_t i = 0; i < p->pass_time_s.size(); ++i) {
      if (pass_time.size() <= i) pass_time.emplace_back();
      pass_time[i].push_back(p->pass_time_s[i]);
    }
  }
  g.reached_criterion = static_cast<int>(ttc.size());
  g.mean_trials_to_criterion = mean_ci(ttc).mean;
  const MeanCi t = mean_ci(total);
  g.mean_total_time_s = t.mean, g.ci_total_time_s = t.half;
  for (std::size_t c = 0; c < kCueCount; ++c) {
    const MeanCi e = mean_ci(errors[c]);
    g.mean_errors[c] = e.mean, g.ci_errors[c] = e.half;
    g.mean_room_time_s[c] = mean_ci(room_time[c]).mean;
  }
  for (const std::vector<double>& v : pass_time) {
    const MeanCi m = mean_ci(v);
    g.mean_pass_time_s.push_back(m.mean), g.ci_pass_time_s.push_back(m.half), g.pass_n.push_back(m.n);
  }
}

}  // namespace

MeanCi mean_ci(const std::vector<double>& values) {
  MeanCi r;
  r.n = static_cast<int>(values.size());
  if (r.n == 0) return {std::nan(""), std::nan(""), 0};  // no mean of nobody: "—" in summary.md
  for (double v : values) r.mean += v;
  r.mean /= r.n;
  if (r.n < 2) return {r.mean, std::nan(""), r.n};
  double ss = 0.0;
  for (double v : values) ss += (v - r.mean) * (v - r.mean);
  r.half = t975(r.n - 1) * std::sqrt(ss / (r.n - 1)) / std::sqrt(static_cast<double>(r.n));
  return r;
}

std::vector<GroupSummary> summarize_groups(const std::vector<ParticipantSummary>& people, bool include_aborted) {
  std::vector<GroupSummary> groups;
  std::vector<std::vector<const ParticipantSummary*>> members;
  for (const ParticipantSummary& p : people) {
    GroupSummary& g = group_of(groups, p);
    const auto gi = static_cast<std::size_t>(&g - groups.data());
    if (members.size() <= gi) members.resize(gi + 1);
    if (!include_aborted && p.aborted()) ++g.excluded;
    else members[gi].push_back(&p);
  }
  for (std::size_t gi = 0; gi < groups.size(); ++gi) fill_group(groups[gi], members[gi]);
  return groups;
}

std::vector<RetestSummary> summarize_retests(const std::vector<ParticipantSummary>& people) {
  std::vector<RetestSummary> out;
  for (const ParticipantSummary& first : people) {
    if (first.session != 1 || !first.ended) continue;
    for (const ParticipantSummary& again : people) {
      if (again.session != 2 || !again.ended || again.participant != first.participant || again.condition != first.condition)
        continue;
      auto it = std::find_if(out.begin(), out.end(), [&](const RetestSummary& r) { return r.condition == first.condition; });
      if (it == out.end()) {
        RetestSummary r;
        r.condition = first.condition;
        it = out.insert(out.end(), r);
      }
      ++it->retested;
      if (again.total_time_s < first.total_time_s) ++it->faster;
    }
  }
  return out;
}

}  // namespace ps::maze
