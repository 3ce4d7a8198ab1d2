// `maze summarize`'s tables: participants.csv, groups.csv, trials.csv, rooms.csv, retest.csv and
// summary.md. A value with nothing behind it (a mean of N = 0, a CI of n < 2: NaN in the
// summaries) is an empty cell in the CSV files, for programs, and "—" in summary.md, for people.
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/file_io.h"
#include "maze/maze_summary.h"

namespace ps::maze {

namespace {

// CSV: NaN (no value) is an empty cell.
std::string fmt(double v, int digits = 3) {
  if (std::isnan(v)) return "";
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

// summary.md: NaN (a mean of nobody) is an em dash, never 0.00.
std::string md_fmt(double v, int digits = 2) { return std::isnan(v) ? "—" : fmt(v, digits); }

std::string csv_header_cues(const std::string& prefix) {
  std::string h;
  for (int c = 0; c < kCueCount; ++c) h += "," + prefix + cue_name(static_cast<Cue>(c));
  return h;
}

// A markdown table's header and separator rows: the `before` columns, one column per cue
// (prefix + the cue's name + suffix), then the `after` columns.
void md_header(std::ostream& md, const std::vector<std::string>& before, const std::string& prefix,
               const std::string& suffix, const std::vector<std::string>& after) {
  md << "|";
  for (const std::string& b : before) md << " " << b << " |";
  for (int c = 0; c < kCueCount; ++c) md << " " << prefix << cue_name(static_cast<Cue>(c)) << suffix << " |";
  for (const std::string& a : after) md << " " << a << " |";
  md << "\n|";
  for (std::size_t i = 0; i < before.size() + static_cast<std::size_t>(kCueCount) + after.size(); ++i) md << "---|";
  md << "\n";
}

}  // namespace

namespace {

// participants.csv, trials.csv and the markdown's participant table.
void participant_tables(const std::vector<ParticipantSummary>& people, std::ostringstream& pc, std::ostringstream& tc,
                        std::ostringstream& md) {
  pc << "participant,session,condition,seed,passes,trials_to_criterion,ended,total_time_s" << csv_header_cues("errors_")
     << csv_header_cues("room_time_s_") << ",end_reason,resumed\n";
  tc << "participant,session,condition,pass,correct,pass_time_s\n";
  md << "## Participants\n\n";
  md_header(md, {"participant", "session", "condition", "seed", "passes", "trials to criterion", "total time (s)"},
            "errors ", "", {"end"});
  for (const ParticipantSummary& p : people) {
    const std::string ttc = p.trials_to_criterion > 0 ? std::to_string(p.trials_to_criterion) : "";
    pc << p.participant << "," << p.session << "," << p.condition << "," << p.seed << "," << p.passes << "," << ttc << ","
       << (p.ended ? "yes" : "no") << "," << fmt(p.total_time_s);
    md << "| " << p.participant << " | " << p.session << " | " << p.condition << " | " << p.seed << " | " << p.passes << " | "
       << (ttc.empty() ? "not reached" : ttc) << " | " << md_fmt(p.total_time_s) << " |";
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
  md << "\n## Groups\n\n";
  md_header(md,
            {"condition", "session", "participants (excluded)", "reached criterion", "mean trials to criterion",
             "mean total time (s) ± 95 % CI"},
            "mean room time ", " (s)", {});
  for (const GroupSummary& g : groups) {
    gc << g.condition << "," << g.session << "," << g.participants << "," << g.reached_criterion << "," << fmt(g.mean_trials_to_criterion)
       << "," << fmt(g.mean_total_time_s);
    md << "| " << g.condition << " | " << g.session << " | " << g.participants << " (" << g.excluded << ") | "
       << g.reached_criterion << " | " << md_fmt(g.mean_trials_to_criterion) << " | " << md_fmt(g.mean_total_time_s)
       << (std::isnan(g.ci_total_time_s) ? "" : " ± " + fmt(g.ci_total_time_s, 2)) << " |";
    for (int c = 0; c < kCueCount; ++c) gc << "," << fmt(g.mean_errors[static_cast<std::size_t>(c)]);
    for (int c = 0; c < kCueCount; ++c)
      gc << "," << fmt(g.mean_room_time_s[static_cast<std::size_t>(c)]), md << " " << md_fmt(g.mean_room_time_s[static_cast<std::size_t>(c)]) << " |";
    gc << "," << g.excluded << "," << fmt(g.ci_total_time_s);
    for (int c = 0; c < kCueCount; ++c) gc << "," << fmt(g.ci_errors[static_cast<std::size_t>(c)]);
    gc << "\n";
    md << "\n";
  }
}

}  // namespace

namespace {

// summary.md's closing paragraph, then its Notes (N = 0 groups, skipped plots), if any.
void md_closing(std::ostringstream& md, const std::vector<std::string>& notes) {
  md << "\nErrors per room are wrong exits summed over all passes; room time is the time from entering a room to "
        "leaving it by an exit, averaged over passes (and over the participants who left that room). Group means "
        "leave out aborted sessions (quit, device_ended, terminated, crashed: the count in brackets) unless "
        "summarize was given --include-aborted; ± is the 95 % confidence interval (Student's t); — is a mean of "
        "nobody (N = 0). Per-room trials: rooms.csv. Plots: errors_by_room.png, time_per_trial.png (unless noted "
        "below).\n";
  if (notes.empty()) return;
  md << "\n## Notes\n\n";
  for (const std::string& n : notes) md << "- " << n << "\n";
}

}  // namespace

Status write_tables(const std::string& dir, const std::vector<ParticipantSummary>& people,
                    const std::vector<GroupSummary>& groups, const std::vector<RetestSummary>& retests,
                    const std::vector<std::string>& notes) {
  std::ostringstream pc, gc, tc, rc, md;
  md << "# Maze summary\n\n";
  participant_tables(people, pc, tc, md);
  group_tables(groups, gc, md);
  rc << "condition,retested,faster_on_retest,share_faster\n";
  if (!retests.empty())
    md << "\n## Retest (session 2 against session 1, Sepulveda-Cervantes et al. §VII)\n\n| condition | retested | faster on retest | share |\n"
          "|---|---|---|---|\n";
  for (const RetestSummary& r : retests) {
    rc << r.condition << "," << r.retested << "," << r.faster << "," << fmt(r.share_faster()) << "\n";
    md << "| " << r.condition << " | " << r.retested << " | " << r.faster << " | " << fmt(100.0 * r.share_faster(), 0) << " % |\n";
  }
  md_closing(md, notes);
  for (const auto& [name, text] : {std::pair<std::string, std::string>{"participants.csv", pc.str()},
                                   {"groups.csv", gc.str()}, {"trials.csv", tc.str()}, {"rooms.csv", rooms_table(people)},
                                   {"retest.csv", rc.str()},
                                   {"summary.md", md.str()}})
    if (Status s = write_file_atomic(dir + "/" + name, text); !s) return s;
  return ok_status();
}

std::vector<std::string> group_notes(const std::vector<GroupSummary>& groups) {
  std::vector<std::string> notes;
  for (const GroupSummary& g : groups) {
    if (g.participants > 0) continue;
    const std::string name = g.condition + " session " + std::to_string(g.session);
    notes.push_back(name + ": N = 0, no mean (" + std::to_string(g.excluded) + " aborted session" +
                    (g.excluded == 1 ? "" : "s") + " left out; --include-aborted counts them)");
  }
  return notes;
}

}  // namespace ps::maze
