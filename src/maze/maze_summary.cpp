#include "maze/maze_summary.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/file_io.h"

namespace ps::maze {

namespace {

using nlohmann::json;

std::string fmt(double v, int digits = 3) {
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
    p.session = j.value("session", 1);
    p.condition = j.at("condition").get<std::string>();
    p.seed = j.at("seed").get<std::uint64_t>();
  } else if (type == "branch") {
    const auto c = static_cast<std::size_t>(cue_index(j.at("cue"), where));
    ++p.trials[c];
    if (!j.at("correct").get<bool>()) ++p.errors[c];
    p.room_time_s[c] += j.at("room_time_s").get<double>();
  } else if (type == "pass_end") {
    ++p.passes;
    p.pass_time_s.push_back(j.at("pass_time_s").get<double>());
    p.pass_correct.push_back(j.at("correct").get<int>());
  } else if (type == "session_end") {
    p.ended = true;
    p.end_reason = j.at("reason").get<std::string>();
    p.trials_to_criterion = j.at("trials_to_criterion").is_null() ? 0 : j.at("trials_to_criterion").get<int>();
  }
}

std::string csv_header_cues(const std::string& prefix) {
  std::string h;
  for (int c = 0; c < kCueCount; ++c) h += "," + prefix + cue_name(static_cast<Cue>(c));
  return h;
}

}  // namespace

Result<ParticipantSummary> summarize_log(const std::string& path) {
  std::ifstream in(path);
  if (!in) return make_error(path + ": cannot open session log (give the session.jsonl a `maze` run wrote)");
  ParticipantSummary p;
  p.log = path;
  bool started = false;
  int n = 0;
  for (std::string line; std::getline(in, line);) {
    const std::string where = path + ":" + std::to_string(++n) + ": ";
    if (line.empty()) continue;
    try {
      const json j = json::parse(line);
      started |= j.at("type") == "session_start";
      if (!started) return make_error(where + "the first line must be the session_start line");
      read_line(p, j, where);
    } catch (const std::exception& e) {
      return make_error(where + "not a maze log line (" + e.what() + "); docs/maze.md lists the schema");
    }
  }
  if (!started) return make_error(path + ":1: empty log: no session_start line");
  return p;
}

std::vector<GroupSummary> summarize_groups(const std::vector<ParticipantSummary>& people) {
  std::vector<GroupSummary> groups;
  for (const ParticipantSummary& p : people) {
    auto it = std::find_if(groups.begin(), groups.end(), [&](const GroupSummary& g) {
      return g.condition == p.condition && g.session == p.session;
    });
    if (it == groups.end()) {
      GroupSummary g;
      g.condition = p.condition;
      g.session = p.session;
      it = groups.insert(groups.end(), g);
    }
    GroupSummary& g = *it;
    ++g.participants;
    if (p.trials_to_criterion > 0) ++g.reached_criterion, g.mean_trials_to_criterion += p.trials_to_criterion;
    g.mean_total_time_s += p.total_time_s;
    for (int c = 0; c < kCueCount; ++c) {
      g.mean_errors[static_cast<std::size_t>(c)] += p.errors[static_cast<std::size_t>(c)];
      g.mean_room_time_s[static_cast<std::size_t>(c)] += p.mean_room_time_s(c);
    }
  }
  for (GroupSummary& g : groups) {
    if (g.reached_criterion > 0) g.mean_trials_to_criterion /= g.reached_criterion;
    g.mean_total_time_s /= g.participants;
    for (int c = 0; c < kCueCount; ++c) {
      g.mean_errors[static_cast<std::size_t>(c)] /= g.participants;
      g.mean_room_time_s[static_cast<std::size_t>(c)] /= g.participants;
    }
    std::vector<int> count;
    for (const ParticipantSummary& p : people) {
      if (p.condition != g.condition || p.session != g.session) continue;
      for (std::size_t i = 0; i < p.pass_time_s.size(); ++i) {
        if (g.mean_pass_time_s.size() <= i) g.mean_pass_time_s.push_back(0.0), count.push_back(0);
        g.mean_pass_time_s[i] += p.pass_time_s[i];
        ++count[i];
      }
    }
    for (std::size_t i = 0; i < count.size(); ++i) g.mean_pass_time_s[i] /= count[i];
  }
  return groups;
}

namespace {

// participants.csv, trials.csv and the markdown's participant table.
void participant_tables(const std::vector<ParticipantSummary>& people, std::ostringstream& pc, std::ostringstream& tc,
                        std::ostringstream& md) {
  pc << "participant,session,condition,seed,passes,trials_to_criterion,ended,total_time_s" << csv_header_cues("errors_")
     << csv_header_cues("room_time_s_") << "\n";
  tc << "participant,session,condition,pass,correct,pass_time_s\n";
  md << "## Participants\n\n| participant | session | condition | seed | passes | trials to criterion | total time (s) |";
  for (int c = 0; c < kCueCount; ++c) md << " errors " << cue_name(static_cast<Cue>(c)) << " |";
  md << "\n|---|---|---|---|---|---|---|";
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
    pc << "\n";
    md << (p.ended ? "" : " (log cut short)") << "\n";
    for (std::size_t i = 0; i < p.pass_time_s.size(); ++i)
      tc << p.participant << "," << p.session << "," << p.condition << "," << i + 1 << "," << p.pass_correct[i] << "," << fmt(p.pass_time_s[i]) << "\n";
  }
}

// groups.csv and the markdown's group table.
void group_tables(const std::vector<GroupSummary>& groups, std::ostringstream& gc, std::ostringstream& md) {
  gc << "condition,session,participants,reached_criterion,mean_trials_to_criterion,mean_total_time_s"
     << csv_header_cues("mean_errors_") << csv_header_cues("mean_room_time_s_") << "\n";
  md << "\n## Groups\n\n| condition | session | participants | reached criterion | mean trials to criterion | mean total time (s) |";
  for (int c = 0; c < kCueCount; ++c) md << " mean room time " << cue_name(static_cast<Cue>(c)) << " (s) |";
  md << "\n|---|---|---|---|---|---|";
  for (int c = 0; c < kCueCount; ++c) md << "---|";
  md << "\n";
  for (const GroupSummary& g : groups) {
    gc << g.condition << "," << g.session << "," << g.participants << "," << g.reached_criterion << "," << fmt(g.mean_trials_to_criterion)
       << "," << fmt(g.mean_total_time_s);
    md << "| " << g.condition << " | " << g.session << " | " << g.participants << " | " << g.reached_criterion << " | "
       << fmt(g.mean_trials_to_criterion, 2) << " | " << fmt(g.mean_total_time_s, 2) << " |";
    for (int c = 0; c < kCueCount; ++c) gc << "," << fmt(g.mean_errors[static_cast<std::size_t>(c)]);
    for (int c = 0; c < kCueCount; ++c)
      gc << "," << fmt(g.mean_room_time_s[static_cast<std::size_t>(c)]), md << " " << fmt(g.mean_room_time_s[static_cast<std::size_t>(c)], 2) << " |";
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
    md << "\n## Retest (session 2 against session 1, seed 003 §VII)\n\n| condition | retested | faster on retest | share |\n"
          "|---|---|---|---|\n";
  for (const RetestSummary& r : retests) {
    rc << r.condition << "," << r.retested << "," << r.faster << "," << fmt(r.share_faster()) << "\n";
    md << "| " << r.condition << " | " << r.retested << " | " << r.faster << " | " << fmt(100.0 * r.share_faster(), 0) << " % |\n";
  }
  md << "\nErrors per room are wrong exits summed over all passes; room time is the time from entering a room to "
        "leaving it by an exit, averaged over passes. Plots: errors_by_room.png, time_per_trial.png.\n";
  for (const auto& [name, text] : {std::pair<std::string, std::string>{"participants.csv", pc.str()},
                                   {"groups.csv", gc.str()}, {"trials.csv", tc.str()}, {"retest.csv", rc.str()},
                                   {"summary.md", md.str()}})
    if (Status s = write_file_atomic(dir + "/" + name, text); !s) return s;
  return ok_status();
}

namespace {

// Mean wrong exits per room, one bar per condition.
void errors_script(std::ostringstream& gp, const std::string& dir, const std::vector<GroupSummary>& groups) {
  gp << "set terminal pngcairo noenhanced size 900,500 font ',10'\nset output '" << dir << "/errors_by_room.png'\n"
     << "set title 'Wrong exits per room (mean per participant) by condition'\nset ylabel 'errors'\n"
     << "set style data histograms\nset style histogram clustered gap 1\nset style fill solid 0.8 border -1\n"
     << "set boxwidth 0.9\nset bmargin 5\nset offsets 0, 0, 0.5, 0\nset yrange [0:*]\nset key top right\nset grid ytics\n"
     << "$errors << EOD\nroom";
  for (const GroupSummary& g : groups)
    gp << " \"" << g.condition << (g.session > 1 ? " session " + std::to_string(g.session) : "") << "\"";
  gp << "\n";
  for (int c = 0; c < kCueCount; ++c) {
    gp << "\"" << cue_label(static_cast<Cue>(c)) << "\\n" << cue_name(static_cast<Cue>(c)) << "\"";
    for (const GroupSummary& g : groups) gp << " " << g.mean_errors[static_cast<std::size_t>(c)];
    gp << "\n";
  }
  gp << "EOD\nplot ";
  for (std::size_t i = 0; i < groups.size(); ++i)
    gp << (i ? ", " : "") << "$errors using " << i + 2 << (i == 0 ? ":xtic(1)" : "") << " title columnheader";
  if (groups.empty()) gp << "0 notitle";
  gp << "\n";
}

// Time per pass, one line per participant, coloured by condition.
void time_script(std::ostringstream& gp, const std::string& dir, const std::vector<ParticipantSummary>& people,
                 const std::vector<GroupSummary>& groups) {
  gp << "\nset output '" << dir << "/time_per_trial.png'\nunset style\nset style data linespoints\n"
     << "set title 'Time per trial (one pass through all rooms)'\nset xlabel 'trial (pass)'\nset ylabel 'time (s)'\n"
     << "set xtics 1\nset yrange [0:*]\nset offsets 0.2, 0.2, 1, 0\nset key outside right\n";
  for (std::size_t k = 0; k < people.size(); ++k) {
    gp << "$p" << k << " << EOD\n";
    for (std::size_t i = 0; i < people[k].pass_time_s.size(); ++i) gp << i + 1 << " " << people[k].pass_time_s[i] << "\n";
    gp << "EOD\n";
  }
  gp << "plot ";
  for (std::size_t k = 0; k < people.size(); ++k) {
    std::size_t group = 0;
    for (std::size_t gi = 0; gi < groups.size(); ++gi)
      if (groups[gi].condition == people[k].condition && groups[gi].session == people[k].session) group = gi;
    gp << (k ? ", " : "") << "$p" << k << " using 1:2 lc " << group + 1 << " pt " << k % 10 + 1 << " title '"
       << people[k].participant << (people[k].session > 1 ? " session " + std::to_string(people[k].session) : "")
       << " (" << people[k].condition << ")'";
  }
  if (people.empty()) gp << "0 notitle";
  gp << "\n";
}

}  // namespace

Status write_plots(const std::string& dir, const std::vector<ParticipantSummary>& people,
                   const std::vector<GroupSummary>& groups) {
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0)
    return make_error("gnuplot not found (install gnuplot-nox): no plots written, the CSV files have the data");
  if (dir.find('\'') != std::string::npos)
    return make_error(dir + ": a directory name with a single quote cannot be handed to gnuplot; choose another --out");
  std::ostringstream gp;
  errors_script(gp, dir, groups);
  time_script(gp, dir, people, groups);
  const std::string script = dir + "/plots.gp";
  if (Status s = write_file_atomic(script, gp.str()); !s) return s;
  if (std::system(("gnuplot '" + script + "' 2> '" + dir + "/plots.log'").c_str()) != 0)
    return make_error("gnuplot failed on " + script + " (its messages: " + dir + "/plots.log)");
  std::remove((dir + "/plots.log").c_str());
  return ok_status();
}

}  // namespace ps::maze
