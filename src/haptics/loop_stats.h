// Rate and period-jitter statistics of a periodic loop (and latencies), from raw samples.
#pragma once

#include <vector>

namespace ps {

struct Percentiles {
  double p50 = 0.0, p99 = 0.0, p999 = 0.0, max = 0.0, mean = 0.0;
  std::size_t count = 0;
};

// Nearest-rank percentiles of `values` (copied; the input is not reordered).
Percentiles percentiles(std::vector<double> values);

}  // namespace ps
