#include "haptics/loop_stats.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace ps {

Percentiles percentiles(std::vector<double> v) { return percentiles_in_place(v); }

Percentiles percentiles_in_place(std::span<double> v) {
  Percentiles p;
  p.count = v.size();
  if (v.empty()) return p;
  std::sort(v.begin(), v.end());
  auto rank = [&](double q) {
    const auto i = static_cast<std::size_t>(std::ceil(q * static_cast<double>(v.size())));
    return v[std::min(v.size() - 1, i == 0 ? 0 : i - 1)];
  };
  p.p50 = rank(0.5);
  p.p99 = rank(0.99);
  p.p999 = rank(0.999);
  p.max = v.back();
  p.mean = std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
  return p;
}

}  // namespace ps
