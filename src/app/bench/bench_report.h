// `pseudoshadow bench`: output side. CSV, a Markdown summary and the gnuplot plots: time vs
// error per knob group with its Pareto front, and the Gabor strategies' speed-ups.
#pragma once

#include <string>
#include <vector>

#include "app/bench/bench_sweep.h"
#include "core/result.h"

namespace ps::bench {

struct RssReport {
  long long kib_512 = -1, kib_2048 = -1;  // peak RSS of `pseudoshadow render`, -1 = not measured
};

std::string csv_text(const std::vector<BenchRow>& rows);  // bench.csv, header line first
std::string summary_markdown(const std::vector<BenchRow>& rows, const SkipRatios& skip,
                             const RssReport& rss, int size);
// The skip-check rows of the pseudo-shadow's cost (one per size) and the table of its passes;
// part of summary_markdown, and all that `bench --shadow-cost` prints.
std::string shadow_cost_rows(const std::vector<ShadowCost>& costs);
std::string shadow_cost_table(const std::vector<ShadowCost>& costs);
// Runs gnuplot: `dir`/bench.png (one time-vs-error panel per knob group, app/bench/bench_plot.h) and
// `dir`/bench_ratios.png (the Gabor strategies' speed-ups over the naive sum), with their
// scripts bench_plot.gp and bench_ratios.gp beside them. An Error says why a plot was not made
// (e.g. gnuplot not installed).
Status write_plots(const std::string& dir, const std::vector<BenchRow>& rows);
// Peak RSS (KiB) of a child `pseudoshadow render` at size^2 (fork + exec of this binary).
// `gl_args`: the --backend / --gpu words for the child render.
Result<long long> render_peak_rss_kib(int size, const std::vector<std::string>& gl_args, const std::string& work_dir);

}  // namespace ps::bench
