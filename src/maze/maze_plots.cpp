// `maze summarize`'s plots (gnuplot): errors per room by condition and time per pass, each
// group's mean with its 95 % confidence interval and N. Lines that would coincide (two
// participants with the same times, two groups with the same means) are drawn a little apart
// along x, each with its own point type and dash, so none hides another.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
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
void errors_script(std::ostringstream& gp, const std::string& dir, const std::vector<GroupSummary>& groups) {
  double top = 1.0;  // whiskers included (gnuplot's autoscale leaves a histogram's error bars out)
  for (const GroupSummary& g : groups)
    for (std::size_t c = 0; c < kCueCount; ++c) top = std::max(top, g.mean_errors[c] + or_zero(g.ci_errors[c]));
  gp << "set terminal pngcairo noenhanced size 900,500 font ',10'\nset output '" << dir << "/errors_by_room.png'\n"
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
  if (groups.empty()) gp << "0 notitle";
  gp << "\n";
}

std::size_t group_index(const std::vector<GroupSummary>& groups, const ParticipantSummary& p) {
  for (std::size_t gi = 0; gi < groups.size(); ++gi)
    if (groups[gi].condition == p.condition && groups[gi].session == p.session) return gi;
  return 0;
}

// True when some participant has a timed pass. Without one (every session quit before its first
// pass ended) gnuplot cannot autoscale x ("x range is invalid") and fails: the axes are then fixed.
bool any_pass_time(const std::vector<ParticipantSummary>& people) {
  return std::any_of(people.begin(), people.end(), [](const ParticipantSummary& p) { return !p.pass_time_s.empty(); });
}

// Spreads n things around 0 by `step` (n = 3: -step, 0, +step).
double spread(std::size_t i, std::size_t n, double step) { return step * (static_cast<double>(i) - 0.5 * (n - 1.0)); }

// Time per pass: each group's mean with 95 % CI and the n behind each point (bold), every
// participant as a thin dashed line in the group's colour.
void time_script(std::ostringstream& gp, const std::string& dir, const std::vector<ParticipantSummary>& people,
                 const std::vector<GroupSummary>& groups) {
  gp << "\nset output '" << dir << "/time_per_trial.png'\nunset style\nset style data linespoints\nset size 1,1\n"
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
  if (!any_pass_time(people)) gp << "set xrange [0.5:1.5]\nset yrange [0:1]\n";  // empty axes (any_pass_time)
  gp << "plot ";
  const char* sep = "";
  for (std::size_t gi = 0; gi < groups.size(); ++gi, sep = ", ")
    gp << sep << "$g" << gi << " using 1:2:3 with yerrorlines lw 2.5 lc " << gi + 1 << " pt " << 5 + 2 * gi << " ps 1.5 dt "
       << gi % 5 + 1 << " title '" << group_title(groups[gi]) << "', $g" << gi
       << " using 1:($2+$3):(sprintf('n=%d', $4)) with labels offset 0,0.8 tc lt " << gi + 1 << " notitle";
  for (std::size_t k = 0; k < people.size(); ++k, sep = ", ")
    gp << sep << "$p" << k << " using 1:2 lw 1 dt 3 lc " << group_index(groups, people[k]) + 1 << " pt " << k % 14 + 1
       << " ps 0.8 title '" << people[k].participant
       << (people[k].session > 1 ? " session " + std::to_string(people[k].session) : "") << "'";
  if (groups.empty() && people.empty()) gp << "0 notitle";
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
