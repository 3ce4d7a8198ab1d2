#include "haptics/loop_stats.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace ps {

Percentiles percentiles(std::span<const double> values) {
  std::vector<double> v(values.begin(), values.end());
  return percentiles_in_place(v);
}

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

namespace {

const double kLogRatio = std::log(StreamingPercentiles::kRatio);

std::size_t bin_count() {
  return static_cast<std::size_t>(std::ceil(std::log(StreamingPercentiles::kMax / StreamingPercentiles::kMin) / kLogRatio));
}

}  // namespace

StreamingPercentiles::StreamingPercentiles() : bins_(bin_count(), 0) {}

void StreamingPercentiles::add(double v) {
  if (std::isnan(v)) return;
  const double i = v > kMin ? std::floor(std::log(v / kMin) / kLogRatio) : 0.0;
  ++bins_[static_cast<std::size_t>(std::min(i, static_cast<double>(bins_.size() - 1)))];
  max_ = count_ == 0 ? v : std::max(max_, v);
  sum_ += v;
  ++count_;
}

Percentiles StreamingPercentiles::percentiles() const {
  Percentiles p;
  p.count = count_;
  if (count_ == 0) return p;
  auto rank = [&](double q) {
    const auto r = std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::ceil(q * static_cast<double>(count_))));
    std::uint64_t seen = 0;
    std::size_t i = 0;
    for (; i + 1 < bins_.size(); ++i)
      if ((seen += bins_[i]) >= r) break;
    return std::min(max_, kMin * std::exp((static_cast<double>(i) + 0.5) * kLogRatio));
  };
  p.p50 = rank(0.5);
  p.p99 = rank(0.99);
  p.p999 = rank(0.999);
  p.max = max_;
  p.mean = sum_ / static_cast<double>(count_);
  return p;
}

}  // namespace ps
