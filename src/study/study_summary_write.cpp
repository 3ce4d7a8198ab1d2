// `study summarize`'s files: participants.csv (one row per participant and condition),
// groups.csv (each condition's mean over participants with its 95 % confidence interval, the
// maze's mean_ci: Student's t), summary.md, and the plot (the maze's draw_plot: gnuplot, drawn
// whole or not at all).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "core/file_io.h"
#include "maze/maze_summary.h"
#include "study/study_summary.h"

namespace ps::study {

namespace {

std::string num(double v) {
  if (!std::isfinite(v)) return "";
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

bool is_threshold(const std::vector<ParticipantResult>& people) { return !people.empty() && people[0].task == "threshold"; }
bool is_targeting(const std::vector<ParticipantResult>& people) { return !people.empty() && people[0].task == "targeting"; }

// A targeting condition's row: ISO 9241-9's measures over its cells, and the Fitts regression of
// the cells' mean movement time on the nominal ID with its 95 % t interval.
void targeting_row(std::ostringstream& o, const ConditionResult& c) {
  int trials = 0, misses = 0;
  double mt = 0.0, we = 0.0;
  int with_we = 0;
  for (const FittsCell& cell : c.fitts.cells) {
    trials += cell.trials;
    misses += cell.misses;
    mt += cell.mean_mt_s * cell.trials;
    if (std::isfinite(cell.effective_width)) {
      we += cell.effective_width / cell.width;
      ++with_we;
    }
  }
  const LinearFit& f = c.fitts.on_id;
  o << num(trials ? 100.0 * misses / trials : NAN) << "," << num(trials ? mt / trials : NAN) << ","
    << num(with_we ? we / with_we : NAN) << "," << num(c.fitts.throughput_bps) << "," << c.fitts.cells_used << ","
    << num(f.intercept) << "," << num(f.intercept_ci.low) << "," << num(f.intercept_ci.high) << "," << num(f.slope) << ","
    << num(f.slope_ci.low) << "," << num(f.slope_ci.high) << "," << num(f.r_squared) << "\n";
}

std::string participants_csv(const std::vector<ParticipantResult>& people) {
  std::ostringstream o;
  const bool th = is_threshold(people), tg = is_targeting(people);
  o << "participant,condition,trials,complete,"
    << (th   ? "threshold,threshold_low,threshold_high,slope,slope_low,slope_high,alpha,beta,lapse,weber,weber_low,weber_high,criterion,"
               "threshold_cred_low,threshold_cred_high,slope_cred_low,slope_cred_high,weber_cred_low,weber_cred_high\n"
        : tg ? "error_percent,movement_time_s,we_over_w,throughput_bps,cells_used,fitts_a_s,fitts_a_low,fitts_a_high,"
               "fitts_b_s_per_bit,fitts_b_low,fitts_b_high,fitts_r2\n"
             : "percent_correct,information_bits,miller_madow_bits,corrected_bits,distinguishable\n");
  for (const ParticipantResult& p : people)
    for (const ConditionResult& c : p.conditions) {
      o << p.participant << "," << c.condition << "," << c.trials << "," << (p.complete ? "yes" : "no") << ",";
      if (tg)
        targeting_row(o, c);
      else if (th)
        o << num(c.boot.threshold) << "," << num(c.boot.threshold_ci.low) << "," << num(c.boot.threshold_ci.high) << ","
          << num(c.boot.slope) << "," << num(c.boot.slope_ci.low) << "," << num(c.boot.slope_ci.high) << ","
          << num(c.fit.params.threshold) << "," << num(c.fit.params.slope) << "," << num(c.fit.params.lapse) << ","
          << num(c.weber) << "," << num(c.weber_ci.low) << "," << num(c.weber_ci.high) << "," << p.criterion << ","
          << num(c.posterior.threshold_ci.low) << "," << num(c.posterior.threshold_ci.high) << ","
          << num(c.posterior.slope_ci.low) << "," << num(c.posterior.slope_ci.high) << "," << num(c.weber_cred.low) << ","
          << num(c.weber_cred.high) << "\n";
      else
        o << num(c.ident.percent_correct) << "," << num(c.ident.information_bits) << "," << num(c.ident.miller_madow_bits)
          << "," << num(c.ident.corrected_bits) << "," << num(c.ident.distinguishable) << "\n";
    }
  return o.str();
}

// Each condition's values of one quantity over the participants who have it.
std::vector<double> values(const std::vector<ParticipantResult>& people, std::size_t c, double (*get)(const ConditionResult&)) {
  std::vector<double> v;
  for (const ParticipantResult& p : people)
    if (c < p.conditions.size() && p.conditions[c].trials > 0 && std::isfinite(get(p.conditions[c]))) v.push_back(get(p.conditions[c]));
  return v;
}

struct Quantity {
  const char* name;
  double (*get)(const ConditionResult&);
};
// The movement time, error rate and We / W of a targeting condition, over its cells' trials.
double mean_mt(const ConditionResult& c) {
  double t = 0.0;
  int n = 0;
  for (const FittsCell& cell : c.fitts.cells) {
    t += cell.mean_mt_s * cell.trials;
    n += cell.trials;
  }
  return n ? t / n : NAN;
}
double error_percent(const ConditionResult& c) {
  int m = 0, n = 0;
  for (const FittsCell& cell : c.fitts.cells) {
    m += cell.misses;
    n += cell.trials;
  }
  return n ? 100.0 * m / n : NAN;
}

std::vector<Quantity> quantities(const std::string& task) {
  if (task == "targeting")
    return {{"throughput_bps", [](const ConditionResult& c) { return c.fitts.throughput_bps; }},
            {"movement_time_s", mean_mt},
            {"error_percent", error_percent},
            {"fitts_b_s_per_bit", [](const ConditionResult& c) { return c.fitts.on_id.computable ? c.fitts.on_id.slope : NAN; }}};
  if (task == "threshold")
    return {{"threshold", [](const ConditionResult& c) { return c.data.size() < 2 ? NAN : c.boot.threshold; }},
            {"slope", [](const ConditionResult& c) { return c.data.size() < 2 ? NAN : c.boot.slope; }},
            {"weber", [](const ConditionResult& c) { return c.data.size() < 2 ? NAN : c.weber; }}};
  return {{"percent_correct", [](const ConditionResult& c) { return c.ident.percent_correct; }},
          {"corrected_bits", [](const ConditionResult& c) { return c.ident.corrected_bits; }},
          {"distinguishable", [](const ConditionResult& c) { return c.ident.distinguishable; }}};
}

std::string groups_csv(const std::vector<ParticipantResult>& people) {
  std::ostringstream o;
  o << "condition,quantity,n,mean,ci95_low,ci95_high\n";
  if (people.empty()) return o.str();
  for (std::size_t c = 0; c < people[0].conditions.size(); ++c)
    for (const Quantity& q : quantities(people[0].task)) {
      const maze::MeanCi m = maze::mean_ci(values(people, c, q.get));
      o << people[0].conditions[c].condition << "," << q.name << "," << m.n << "," << num(m.mean) << ","
        << num(m.mean - m.half) << "," << num(m.mean + m.half) << "\n";
    }
  return o.str();
}

std::string summary_md(const std::vector<ParticipantResult>& people, const std::string& groups,
                       const std::vector<std::string>& notes) {
  std::ostringstream o;
  const ParticipantResult& first = people.front();
  o << "# " << first.experiment << ": summary\n\n" << people.size()
    << (people.size() == 1 ? " participant" : " participants") << ", task " << first.task;
  if (is_threshold(people))
    o << "; thresholds at " << first.criterion << " correct (maximum likelihood, lapse free in [0, 0.06]), 95 % "
      << "bootstrap intervals and 95 % credible intervals (participants.csv's *_cred_* columns: the posterior with "
      << "flat priors over the fit's range, the slope within the range Psi assumes; an adaptive run's bootstrap "
      << "intervals run narrow, these hold the truth at their nominal rate); Weber fractions against the reference "
      << first.reference;
  if (is_targeting(people)) {
    o << "; ISO 9241-9 per Soukoreff & MacKenzie (2004): effective width We = 4.133 SDx of the end points along "
      << "each movement's axis, throughput as the mean over the (D, W) cells of IDe / MT; the Fitts regression "
      << "MT = a + b ID of the cells' mean times on the nominal ID";
    if (first.pointer_truth)
      o << ". The simulated participants' own law: a = " << first.pointer_truth->a_s << " s, b = " << first.pointer_truth->b_s_per_bit
        << " s/bit, end-point spread " << first.pointer_truth->spread << " (We = W on average at 1)";
  }
  o << ".\n\n## Each condition over participants (mean, 95 % CI: Student's t)\n\n```\n" << groups << "```\n\n";
  if (people.size() == 1) o << "With one participant the intervals over participants are empty: a t interval needs two.\n\n";
  o << "## Participants\n\nparticipants.csv: one row per participant and condition.\n\n";
  for (const ParticipantResult& p : people)
    o << "- " << p.participant << ": " << p.log << (p.complete ? "" : " (not complete)") << (p.torn.empty() ? "" : "; " + p.torn) << "\n";
  if (!notes.empty()) o << "\n## Notes\n\n";
  for (const std::string& n : notes) o << "- " << n << "\n";
  return o.str();
}

// gnuplot's psi(x) of a fit, for one curve.
std::string curve(Shape shape, const PsychometricParams& p) {
  std::ostringstream o;
  o << p.guess << " + (1 - " << p.guess << " - " << p.lapse << ") * ";
  if (shape == Shape::kWeibull) o << "(x > 0 ? 1 - exp(-(x / " << p.threshold << ") ** " << p.slope << ") : 0)";
  else if (shape == Shape::kLogistic) o << "1 / (1 + exp(-" << p.slope << " * (x - " << p.threshold << ")))";
  else o << "norm(" << p.slope << " * (x - " << p.threshold << "))";
  return o.str();
}

void psychometric_script(std::ostringstream& gp, const std::string& png, const std::vector<ParticipantResult>& people) {
  gp << "set terminal pngcairo noenhanced size 900,600 font ',10'\nset output '" << png << "'\n"
     << "set title 'Proportion correct by level: data (size by trials), fits, thresholds with 95 % intervals (bars)'\n"
     << "set xlabel 'level (difference from the reference)'\nset ylabel 'proportion correct'\nset yrange [0.3:1.05]\n"
     << "set key outside right\nset grid\nset samples 400\n"
     << (people.front().shape == Shape::kWeibull ? "set logscale x\n" : "");  // Weibull: levels judged in ratio
  std::string plot;
  int i = 0;
  for (const ParticipantResult& p : people)
    for (const ConditionResult& c : p.conditions) {
      if (c.data.size() < 2) continue;
      gp << "$d" << ++i << " << EOD\n";
      for (const LevelCounts& l : c.data) gp << l.level << " " << double(l.correct) / l.trials << " " << l.trials << "\n";
      gp << "EOD\n";
      const std::string name = p.participant + " " + c.condition;
      plot += (plot.empty() ? "plot " : ", ") + std::string("$d") + std::to_string(i) + " using 1:2:(0.4 + sqrt($3) / 3) with points pt 7 ps variable lc " +
              std::to_string(i) + " notitle, " + curve(p.shape, c.fit.params) + " lc " + std::to_string(i) + " title '" + name + "'";
      // The threshold at the criterion with its 95 % credible interval (the one that holds the
      // truth at its rate, posterior.h), a bar across the curve.
      const Interval& ci = c.posterior.threshold_ci;
      if (std::isfinite(c.boot.threshold) && std::isfinite(ci.low) && std::isfinite(ci.high) && ci.high > ci.low) {
        gp << "$t" << i << " << EOD\n"
           << c.boot.threshold << " " << p.criterion << " " << ci.low << " " << ci.high << "\nEOD\n";
        plot += ", $t" + std::to_string(i) + " using 1:2:3:4 with xerrorbars pt 9 ps 1.5 lc " + std::to_string(i) + " notitle";
      }
    }
  // The simulated participants' own function, when they share one: the truth the fits estimate.
  bool same = people.front().truth.has_value();
  for (const ParticipantResult& p : people)
    same = same && p.truth && p.truth_shape == people.front().truth_shape &&
           p.truth->threshold == people.front().truth->threshold && p.truth->slope == people.front().truth->slope &&
           p.truth->lapse == people.front().truth->lapse;
  if (same && !plot.empty())
    plot += ", " + curve(people.front().truth_shape, *people.front().truth) + " lc black lw 3 dt 2 title 'true (simulated)'";
  gp << plot << "\n";
}

// Each participant's cells, mean movement time against the nominal ID, a colour per condition,
// the conditions' mean regression lines, and the simulated law when the participants share one.
void fitts_script(std::ostringstream& gp, const std::string& png, const std::vector<ParticipantResult>& people) {
  gp << "set terminal pngcairo noenhanced size 900,600 font ',10'\nset output '" << png << "'\n"
     << "set title 'Movement time by index of difficulty (points: the (D, W) cells of every participant; lines: the mean fits)'\n"
     << "set xlabel 'ID = log2(D / W + 1), bits'\nset ylabel 'mean movement time, s'\nset key outside right\nset grid\n";
  std::string plot;
  for (std::size_t c = 0; c < people.front().conditions.size(); ++c) {
    gp << "$c" << c << " << EOD\n";
    double a = 0.0, b = 0.0;
    int n = 0;
    for (const ParticipantResult& p : people) {
      if (c >= p.conditions.size()) continue;
      for (const FittsCell& cell : p.conditions[c].fitts.cells)
        if (cell.trials > 0) gp << cell.id_bits << " " << cell.mean_mt_s << "\n";
      if (p.conditions[c].fitts.on_id.computable) {
        a += p.conditions[c].fitts.on_id.intercept;
        b += p.conditions[c].fitts.on_id.slope;
        ++n;
      }
    }
    gp << "EOD\n";
    const std::string colour = std::to_string(c + 1), name = people.front().conditions[c].condition;
    plot += (plot.empty() ? "plot " : ", ") + std::string("$c") + std::to_string(c) + " using 1:2 with points pt 7 lc " + colour +
            " title '" + name + "'";
    if (n > 0)
      plot += ", " + num(a / n) + " + " + num(b / n) + " * x lc " + colour + " lw 2 title '" + name + " mean fit'";
  }
  bool same = people.front().pointer_truth.has_value();
  for (const ParticipantResult& p : people)
    same = same && p.pointer_truth && p.pointer_truth->a_s == people.front().pointer_truth->a_s &&
           p.pointer_truth->b_s_per_bit == people.front().pointer_truth->b_s_per_bit;
  if (same && !plot.empty())
    plot += ", " + num(people.front().pointer_truth->a_s) + " + " + num(people.front().pointer_truth->b_s_per_bit) +
            " * x lc black lw 3 dt 2 title 'true (simulated)'";
  gp << plot << "\n";
}

void confusion_script(std::ostringstream& gp, const std::string& png, const std::vector<ParticipantResult>& people) {
  const std::vector<std::string>& m = people.front().materials;
  gp << "set terminal pngcairo noenhanced size 700,600 font ',10'\nset output '" << png << "'\n"
     << "set title 'Confusion matrix, all participants and conditions (rows: shown, columns: answered)'\n"
     << "set xlabel 'answered'\nset ylabel 'shown'\nset yrange [] reverse\nset palette grey negative\n";
  std::string tics;
  for (std::size_t j = 0; j < m.size(); ++j) tics += (j ? ", '" : "'") + m[j] + "' " + std::to_string(j);
  gp << "set xtics (" << tics << ")\nset ytics (" << tics << ")\n$m << EOD\n";
  for (std::size_t i = 0; i < m.size(); ++i) {
    for (std::size_t j = 0; j < m.size(); ++j) {
      int n = 0;
      for (const ParticipantResult& p : people)
        for (const ConditionResult& c : p.conditions) n += c.confusion[i][j];
      gp << (j ? " " : "") << n;
    }
    gp << "\n";
  }
  gp << "EOD\nplot $m matrix with image notitle, $m matrix using 1:2:(sprintf('%d', $3)) with labels notitle\n";
}

}  // namespace

Status write_study_summary(const std::string& dir, const std::vector<ParticipantResult>& people,
                           std::vector<std::string>& notes) {
  if (people.empty()) return make_error("no participants to summarize");
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return make_error(dir + ": cannot create the summary's folder: " + ec.message());
  const bool th = is_threshold(people), tg = is_targeting(people);
  const std::string plot = th ? "psychometric.png" : tg ? "fitts.png" : "confusion.png";
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0)
    notes.push_back(plot + " skipped: gnuplot not found (install gnuplot-nox); the CSV files have the data");
  else if (dir.find('\'') != std::string::npos)
    notes.push_back(plot + " skipped: a folder name with a single quote cannot be handed to gnuplot");
  else if (Status s = maze::draw_plot(dir, plot, [&](std::ostringstream& gp, const std::string& png) {
             if (th) psychometric_script(gp, png, people);
             else if (tg) fitts_script(gp, png, people);
             else confusion_script(gp, png, people);
           });
           !s)
    notes.push_back(plot + " skipped: " + s.error().message);
  const std::string groups = groups_csv(people);
  for (const auto& [name, text] : {std::pair<std::string, std::string>{"participants.csv", participants_csv(people)},
                                  {"groups.csv", groups}, {"summary.md", summary_md(people, groups, notes)}})
    if (Status s = write_file_atomic(dir + "/" + name, text); !s) return s;
  return ok_status();
}

}  // namespace ps::study
