// `maze summarize`'s plots (gnuplot): errors per room by condition and time per pass, each
// group's mean with its 95 % confidence interval and N. Lines that would coincide (two
// participants with the same times, two groups with the same means) are drawn a little apart
// along x, each with its own point type and dash, so none hides another. A plot with nothing to
// draw is skipped with its reason (plan_plots), and one gnuplot fails on leaves nothing behind:
// each is drawn to FILE.partial and renamed when gnuplot succeeded and wrote something.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <sstream>

#include "core/file_io.h"
#include "maze/maze_summary.h"

namespace ps::maze {

namespace {

double or_zero(double v) { return std::isnan(v) ? 0.0 : v; }  // no CI (N < 2): a bar of zero

std::string group_title(const GroupSummary& g) {
  return g.condition + (g.session > 1 ? " session " + std::to_string(g.session) : "") + " (N = " +
         std::to_string(g.participants) + (g.excluded > 0 ? ", " + std::to_string(g.excluded) + " aborted left out" : "") + ")";
}

// Mean wrong exits per room, one bar per condition, with 95 % CI whiskers.
// Only groups with someone in their means (N > 0): a bar of nobody would read as 0 errors.
void errors_script(std::ostringstream& gp, const std::string& png, const std::vector<GroupSummary>& all) {
  std::vector<GroupSummary> groups;
  for (const GroupSummary& g : all)
    if (g.participants > 0) groups.push_back(g);
  double top = 1.0;  // whiskers included (gnuplot's autoscale leaves a histogram's error bars out)
  for (const GroupSummary& g : groups)
    for (std::size_t c = 0; c < kCueCount; ++c) top = std::max(top, g.mean_errors[c] + or_zero(g.ci_errors[c]));
  gp << "set terminal pngcairo noenhanced size 900,500 font ',10'\nset output '" << png << "'\n"
     << "set title 'Wrong exits per room (mean per participant, whiskers: 95 % CI) by condition'\nset ylabel 'errors'\n"
     << "set style data histograms\nset style histogram errorbars gap 1 lw 1.5\nset style fill solid 0.8 border -1\n"
     << "set boxwidth 0.9\nset bmargin 5\nset yrange [0:" << 1.1 * top << "]\nset key top right\nset grid ytics\n"
     << "$errors << EOD\n";
  for (int c = 0; c < kCueCount; ++c) {
    gp << "\"" << cue_label(static_cast<Cue>(c)) << "\\n" << cue_name(static_cast<Cue>(c)) << "\"";
    for (const GroupSummary& g : groups)
      gp << " " << g.mean_errors[static_cast<std::size_t>(c)] << " " << or_zero(g.ci_errors[static_cast<std::size_t>(c)]);
    gp << "\n";
  }
  gp << "EOD\nplot ";
  for (std::size_t i = 0; i < groups.size(); ++i)
    gp << (i ? ", " : "") << "$errors using " << 2 * i + 2 << ":" << 2 * i + 3 << (i == 0 ? ":xtic(1)" : "") << " title '"
       << group_title(groups[i]) << "'";
  gp << "\n";
}

std::size_t group_index(const std::vector<GroupSummary>& groups, const ParticipantSummary& p) {
  for (std::size_t gi = 0; gi < groups.size(); ++gi)
    if (groups[gi].condition == p.condition && groups[gi].session == p.session) return gi;
  return 0;
}

// Spreads n things around 0 by `step` (n = 3: -step, 0, +step).
double spread(std::size_t i, std::size_t n, double step) { return step * (static_cast<double>(i) - 0.5 * (n - 1.0)); }

// The time plot's plot command: the groups' means (those with a pass: a group of N = 0 has
// none) and every participant with a complete pass; the data blocks are $gI and $pK.
void time_plot_command(std::ostringstream& gp, const std::vector<ParticipantSummary>& people,
                       const std::vector<GroupSummary>& groups) {
  gp << "plot ";
  const char* sep = "";
  for (std::size_t gi = 0; gi < groups.size(); ++gi) {
    if (groups[gi].mean_pass_time_s.empty()) continue;
    gp << sep << "$g" << gi << " using 1:2:3 with yerrorlines lw 2.5 lc " << gi + 1 << " pt " << 5 + 2 * gi << " ps 1.5 dt "
       << gi % 5 + 1 << " title '" << group_title(groups[gi]) << "', $g" << gi
       << " using 1:($2+$3):(sprintf('n=%d', $4)) with labels offset 0,0.8 tc lt " << gi + 1 << " notitle";
    sep = ", ";
  }
  for (std::size_t k = 0; k < people.size(); ++k) {
    if (people[k].pass_time_s.empty()) continue;
    gp << sep << "$p" << k << " using 1:2 lw 1 dt 3 lc " << group_index(groups, people[k]) + 1 << " pt " << k % 14 + 1
       << " ps 0.8 title '" << people[k].participant
       << (people[k].session > 1 ? " session " + std::to_string(people[k].session) : "") << "'";
    sep = ", ";
  }
  gp << "\n";
}

// Time per pass: each group's mean with 95 % CI and the n behind each point (bold), every
// participant as a thin dashed line in the group's colour.
void time_script(std::ostringstream& gp, const std::string& png, const std::vector<ParticipantSummary>& people,
                 const std::vector<GroupSummary>& groups) {
  gp << "set terminal pngcairo noenhanced size 900,500 font ',10'\nset output '" << png << "'\n"
     << "set style data linespoints\n"
     << "set title 'Time per trial (one pass through all rooms): group mean, 95 % CI, n per point'\n"
     << "set xlabel 'trial (pass)'\nset ylabel 'time (s)'\nset xtics 1\nset yrange [0:*]\nset offsets 0.3, 0.3, 1, 0\n"
     << "set key outside right\n";
  for (std::size_t k = 0; k < people.size(); ++k) {
    gp << "$p" << k << " << EOD\n";
    for (std::size_t i = 0; i < people[k].pass_time_s.size(); ++i)
      gp << i + 1 + spread(k, people.size(), 0.03) << " " << people[k].pass_time_s[i] << "\n";
    gp << "EOD\n";
  }
  for (std::size_t gi = 0; gi < groups.size(); ++gi) {
    gp << "$g" << gi << " << EOD\n";
    for (std::size_t i = 0; i < groups[gi].mean_pass_time_s.size(); ++i)
      gp << i + 1 + spread(gi, groups.size(), 0.12) << " " << groups[gi].mean_pass_time_s[i] << " "
         << or_zero(groups[gi].ci_pass_time_s[i]) << " " << groups[gi].pass_n[i] << "\n";
    gp << "EOD\n";
  }
  time_plot_command(gp, people, groups);
}

// Why the errors plot has nothing to draw ("": it has): no one in any group's means, or no room
// left by an exit by those who are.
std::string errors_skip(const std::vector<ParticipantSummary>& people, const std::vector<GroupSummary>& groups) {
  int in_means = 0, excluded = 0;
  for (const GroupSummary& g : groups) in_means += g.participants, excluded += g.excluded;
  if (people.empty()) return "no session logs";
  if (in_means == 0)
    return "no session in the group means (" + std::to_string(excluded) + " aborted left out; --include-aborted counts them)";
  for (const GroupSummary& g : groups)
    for (const ParticipantSummary& p : people)
      if (p.condition == g.condition && p.session == g.session && g.participants > 0)
        for (int t : p.trials)
          if (t > 0) return "";
  return "no room left by an exit";
}

}  // namespace

// Runs `script` (written beside the plot) through gnuplot into png + ".partial", renamed to png
// when gnuplot succeeded and wrote something; on any failure nothing is left at either name.
Status draw_plot(const std::string& dir, const std::string& png_name,
            const std::function<void(std::ostringstream&, const std::string&)>& script) {
  const std::string png = dir + "/" + png_name, partial = png + ".partial";
  const std::string stem = png_name.substr(0, png_name.size() - 4);  // without ".png"
  const std::string gp_path = dir + "/" + stem + ".gp", log = dir + "/" + stem + ".log";
  std::ostringstream gp;
  script(gp, partial);
  if (Status s = write_file_atomic(gp_path, gp.str()); !s) return s;
  std::error_code ec;
  const bool ran = std::system(("gnuplot '" + gp_path + "' 2> '" + log + "'").c_str()) == 0;
  if (!ran || !std::filesystem::exists(partial, ec) || std::filesystem::file_size(partial, ec) == 0) {
    std::filesystem::remove(partial, ec);
    return make_error("gnuplot failed on " + gp_path + ": no " + png_name + " written (its messages: " + log + ")");
  }
  std::filesystem::remove(log, ec);
  return rename_durable(partial, png);
}

std::vector<PlotPlan> plan_plots(const std::vector<ParticipantSummary>& people, const std::vector<GroupSummary>& groups) {
  bool any_pass = false;
  for (const ParticipantSummary& p : people) any_pass |= !p.pass_time_s.empty();
  return {{PlotPlan::Kind::kErrorsByRoom, "errors_by_room.png", errors_skip(people, groups)},
          {PlotPlan::Kind::kTimePerTrial, "time_per_trial.png",
           any_pass ? "" : "no completed trials (a trial: one pass through all six rooms)"}};
}

Status write_plots(const std::string& dir, const std::vector<ParticipantSummary>& people,
                   const std::vector<GroupSummary>& groups) {
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0)
    return make_error("gnuplot not found (install gnuplot-nox): no plots written, the CSV files have the data");
  if (dir.find('\'') != std::string::npos)
    return make_error(dir + ": a directory name with a single quote cannot be handed to gnuplot; choose another --out");
  for (const PlotPlan& plan : plan_plots(people, groups)) {
    if (!plan.skipped.empty()) continue;
    const bool errors = plan.kind == PlotPlan::Kind::kErrorsByRoom;
    const Status s = draw_plot(dir, plan.file, [&](std::ostringstream& gp, const std::string& png) {
      if (errors) errors_script(gp, png, groups);
      else time_script(gp, png, people, groups);
    });
    if (!s) return s;
  }
  return ok_status();
}

}  // namespace ps::maze
