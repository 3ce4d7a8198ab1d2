// `pseudoshadow bench`: output side. CSV, a Markdown summary and a gnuplot time-vs-error plot
// with each knob group's Pareto front drawn as a line.
#pragma once

#include <string>
#include <vector>

#include "app/bench_sweep.h"
#include "core/result.h"

namespace ps::bench {

struct RssReport {
  long long kib_512 = -1, kib_2048 = -1;  // peak RSS of `pseudoshadow render`, -1 = not measured
};

std::string csv_text(const std::vector<BenchRow>& rows);  // bench.csv, header line first
std::string summary_markdown(const std::vector<BenchRow>& rows, const SkipRatios& skip,
                             const RssReport& rss, int size);
// Runs gnuplot; an Error says why no plot was made (e.g. gnuplot not installed).
Status write_plot(const std::string& png_path, const std::string& work_dir,
                  const std::vector<BenchRow>& rows);
// Peak RSS (KiB) of a child `pseudoshadow render` at size^2 (fork + exec of this binary).
Result<long long> render_peak_rss_kib(int size, const std::string& backend, const std::string& work_dir);

}  // namespace ps::bench
