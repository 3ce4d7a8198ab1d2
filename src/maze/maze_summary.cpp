#include "maze/maze_summary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/file_io.h"
#include "core/json_int.h"
#include "maze/maze_log.h"

namespace ps::maze {

namespace {

using nlohmann::json;

std::string fmt(double v, int digits = 3) {
  if (std::isnan(v)) return "";  // a CI of fewer than two participants: no number
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

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
    p.end_reason.clear();
  } else if (type == "session_end") {
    p.ended = true;
    p.end_reason = j.at("reason").get<std::string>();
    p.trials_to_criterion = j.at("trials_to_criterion").is_null() ? 0 : json_int<int>(j.at("trials_to_criterion"), "trials_to_criterion");
  }
}

std::string csv_header_cues(const std::string& prefix) {
  std::string h;
  for (int c = 0; c < kCueCount; ++c) h += "," + prefix + cue_name(static_cast<Cue>(c));
  return h;
}

}  // namespace

Result<ParticipantSummary> summarize_log(const std::string& path) {
  ParticipantSummary p;
  p.log = path;
  auto n = read_session_log(path, "give the session.jsonl a `maze` run wrote", "",
                            [&](const json& j, const std::string& where) { read_line(p, j, where); });
  if (!n) return n.error();
  return p;
}

namespace {

// Student's t at 0.975 for df degrees of freedom (two-sided 95 %); 1.96 past 30 (within 2 %).
double t975(int df) {
  static constexpr double kT[30] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                                    2.201,  2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086,
                                    2.080,  2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};
  return df >= 1 && df <= 30 ? kT[df - 1] : 1.96;
}

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
      room_time[c].push_back(p->mean_room_time_s(static_cast<int>(c)));
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
  if (r.n == 0) return {0.0, std::nan(""), 0};
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

namespace {

// participants.csv, trials.csv and the markdown's participant table.
void participant_tables(const std::vector<ParticipantSummary>& people, std::ostringstream& pc, std::ostringstream& tc,
                        std::ostringstream& md) {
  pc << "participant,session,condition,seed,passes,trials_to_criterion,ended,total_time_s" << csv_header_cues("errors_")
     << csv_header_cues("room_time_s_") << ",end_reason,resumed\n";
  tc << "participant,session,condition,pass,correct,pass_time_s\n";
  md << "## Participants\n\n| participant | session | condition | seed | passes | trials to criterion | total time (s) |";
  for (int c = 0; c < kCueCount; ++c) md << " errors " << cue_name(static_cast<Cue>(c)) << " |";
  md << " end |\n|---|---|---|---|---|---|---|---|";
  for (int c = 0; c < kCueCount; ++c) md << "---|";
  md << "\n";
  for (const ParticipantSummary& p : people) {
    const std::string ttc = p.trials_to_criterion > 0 ? std::to_string(p.trials_to_criterion) : "";
    pc << p.participant << "," << p.session << "," << p.condition << "," << p.seed << "," << p.passes << "," << ttc << ","
       << (p.ended ? "yes" : "no") << "," << fmt(p.total_time_s);
    md << "| " << p.participant << " | " << p.session << " | " << p.condition << " | " << p.seed << " | " << p.passes << " | "
       << (ttc.empty() ? "not reached" : ttc) << " | " << fmt(p.total_time_s, 2) << " |";
    for (int c = 0; c < kCueCount; ++c) pc << "," << p.errors[static_cast<std::size_t>(c)], md << " " << p.errors[static_cast<std::size_t>(c)] << " |";
    for (int c = 0; c < kCueCount; ++c) pc << "," << fmt(p.mean_room_time_s(c));
    pc << "," << p.end_reason_or_crashed() << "," << p.resumed << "\n";
    md << " " << p.end_reason_or_crashed() << (p.ended ? "" : " (log cut short)")
       << (p.resumed > 0 ? ", resumed " + std::to_string(p.resumed) + "x" : "") << " |\n";
    for (std::size_t i = 0; i < p.pass_time_s.size(); ++i)
      tc << p.participant << "," << p.session << "," << p.condition << "," << i + 1 << "," << p.pass_correct[i] << "," << fmt(p.pass_time_s[i]) << "\n";
  }
}

// rooms.csv: one row per room left, every participant.
std::string rooms_table(const std::vector<ParticipantSummary>& people) {
  std::ostringstream rc;
  rc << "participant,condition,session,pass,room,cue,exit,correct,time_s,path_mm,contacts_floor,contacts_wall,"
        "contacts_ceiling,contacts_hidden\n";
  for (const ParticipantSummary& p : people)
    for (const RoomTrial& r : p.rooms) {
      rc << p.participant << "," << p.condition << "," << p.session << "," << r.pass << "," << r.room << "," << r.cue << ","
         << r.exit << "," << (r.correct ? "yes" : "no") << "," << fmt(r.time_s) << "," << fmt(r.path_mm, 2);
      for (int k : r.contacts) rc << "," << k;
      rc << "\n";
    }
  return rc.str();
}

// groups.csv and the markdown's group table.
void group_tables(const std::vector<GroupSummary>& groups, std::ostringstream& gc, std::ostringstream& md) {
  gc << "condition,session,participants,reached_criterion,mean_trials_to_criterion,mean_total_time_s"
     << csv_header_cues("mean_errors_") << csv_header_cues("mean_room_time_s_") << ",excluded,ci95_total_time_s"
     << csv_header_cues("ci95_errors_") << "\n";
  md << "\n## Groups\n\n| condition | session | participants (excluded) | reached criterion | mean trials to criterion | mean total time (s) ± 95 % CI |";
  for (int c = 0; c < kCueCount; ++c) md << " mean room time " << cue_name(static_cast<Cue>(c)) << " (s) |";
  md << "\n|---|---|---|---|---|---|";
  for (int c = 0; c < kCueCount; ++c) md << "---|";
  md << "\n";
  for (const GroupSummary& g : groups) {
    gc << g.condition << "," << g.session << "," << g.participants << "," << g.reached_criterion << "," << fmt(g.mean_trials_to_criterion)
       << "," << fmt(g.mean_total_time_s);
    md << "| " << g.condition << " | " << g.session << " | " << g.participants << " (" << g.excluded << ") | "
       << g.reached_criterion << " | " << fmt(g.mean_trials_to_criterion, 2) << " | " << fmt(g.mean_total_time_s, 2)
       << (std::isnan(g.ci_total_time_s) ? "" : " ± " + fmt(g.ci_total_time_s, 2)) << " |";
    for (int c = 0; c < kCueCount; ++c) gc << "," << fmt(g.mean_errors[static_cast<std::size_t>(c)]);
    for (int c = 0; c < kCueCount; ++c)
      gc << "," << fmt(g.mean_room_time_s[static_cast<std::size_t>(c)]), md << " " << fmt(g.mean_room_time_s[static_cast<std::size_t>(c)], 2) << " |";
    gc << "," << g.excluded << "," << fmt(g.ci_total_time_s);
    for (int c = 0; c < kCueCount; ++c) gc << "," << fmt(g.ci_errors[static_cast<std::size_t>(c)]);
    gc << "\n";
    md << "\n";
  }
}

}  // namespace

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

Status write_tables(const std::string& dir, const std::vector<ParticipantSummary>& people,
                    const std::vector<GroupSummary>& groups, const std::vector<RetestSummary>& retests) {
  std::ostringstream pc, gc, tc, rc, md;
  md << "# Maze summary\n\n";
  participant_tables(people, pc, tc, md);
  group_tables(groups, gc, md);
  rc << "condition,retested,faster_on_retest,share_faster\n";
  if (!retests.empty())
    md << "\n## Retest (session 2 against session 1, Sepulveda-Cervantes et al. §VII)\n\n"
          "| condition | retested | faster on retest | share |\n|---|---|---|---|\n";
  for (const RetestSummary& r : retests) {
    rc << r.condition << "," << r.retested << "," << r.faster << "," << fmt(r.share_faster()) << "\n";
    md << "| " << r.condition << " | " << r.retested << " | " << r.faster << " | " << fmt(100.0 * r.share_faster(), 0) << " % |\n";
  }
  md << "\nErrors per room are wrong exits summed over all passes; room time is the time from entering a room to "
        "leaving it by an exit, averaged over passes. Group means leave out aborted sessions (quit, device_ended, "
        "crashed: the count in brackets) unless summarize was given --include-aborted; ± is the 95 % confidence "
        "interval (Student's t). Per-room trials: rooms.csv. Plots: errors_by_room.png, time_per_trial.png.\n";
  for (const auto& [name, text] : {std::pair<std::string, std::string>{"participants.csv", pc.str()},
                                   {"groups.csv", gc.str()}, {"trials.csv", tc.str()}, {"rooms.csv", rooms_table(people)},
                                   {"retest.csv", rc.str()},
                                   {"summary.md", md.str()}})
    if (Status s = write_file_atomic(dir + "/" + name, text); !s) return s;
  return ok_status();
}

}  // namespace ps::maze
