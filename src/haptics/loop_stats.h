// Rate and period-jitter statistics of a periodic loop (and latencies), from raw samples, and
// the fixed-capacity log the haptic thread keeps them in.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace ps {

struct Percentiles {
  double p50 = 0.0, p99 = 0.0, p999 = 0.0, max = 0.0, mean = 0.0;
  std::size_t count = 0;
};

// Nearest-rank percentiles of `values` (copied; the input is not reordered).
Percentiles percentiles(std::span<const double> values);
// The same, sorting `values` in place: no allocation (the haptic thread's per-second HUD numbers).
Percentiles percentiles_in_place(std::span<double> values);

// A log of samples whose storage is allocated and written once, at construction: push() beyond
// the capacity drops the sample and returns false. The haptic thread appends to it at 1 kHz,
// where a std::vector growing past its reservation would reallocate (and copy megabytes)
// mid-tick. Written at construction (zeros), every page is resident from the start: appending
// never takes a page fault (a reservation only faults its pages in as it fills, one every 512
// samples on the haptic thread), and the program's RSS does not climb while the log fills (the
// period log's 4.6 MiB took the first 10 minutes of every soak).
class BoundedLog {
 public:
  explicit BoundedLog(std::size_t capacity) : storage_(capacity, 0.0) {}
  bool push(double v) {
    if (size_ == storage_.size()) return false;
    storage_[size_++] = v;  // within the storage: never allocates
    return true;
  }
  void clear() { size_ = 0; }  // keeps the storage
  std::size_t size() const { return size_; }
  std::size_t capacity() const { return storage_.size(); }
  std::span<const double> values() const { return {storage_.data(), size_}; }
  std::span<double> mutable_values() { return {storage_.data(), size_}; }

 private:
  std::vector<double> storage_;
  std::size_t size_ = 0;
};

// Percentiles of a stream of values in memory fixed at construction, for a program that runs
// for hours (`run`'s frame times and latencies, summed up at exit: a vector of every frame grew
// without end, ~2 MiB an hour at 40 frames a second). Each value counts in a bin of a
// logarithmic scale, kRatio wide, from kMin up; a percentile is its bin's geometric centre
// (nearest rank, as percentiles() counts it), within half a bin, 0.05 %, of the exact one
// for values in [kMin, kMax]; the count, the mean and the max are exact. Values at or below
// kMin count in the first bin, at or above kMax in the last.
class StreamingPercentiles {
 public:
  static constexpr double kMin = 1e-3, kMax = 1e6, kRatio = 1.001;
  StreamingPercentiles();
  void add(double v);  // never allocates; NaN is not counted
  Percentiles percentiles() const;
  std::size_t count() const { return count_; }

 private:
  std::vector<std::uint64_t> bins_;
  std::size_t count_ = 0;
  double sum_ = 0.0, max_ = 0.0;
};

}  // namespace ps
