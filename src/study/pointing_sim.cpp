#include "study/pointing_sim.h"

#include <cmath>
#include <numbers>

#include "study/fit.h"

namespace ps::study {

SimulatedPointer::SimulatedPointer(PointerParams params, std::uint64_t seed) : params_(params), rng_(seed) {}

double SimulatedPointer::normal() {
  // Box-Muller (both of each pair used): std::normal_distribution is implementation-defined, so
  // it would give other trials with another standard library; 1 - uniform01 is in (0, 1], so the
  // log is finite.
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  const double r = std::sqrt(-2.0 * std::log(1.0 - uniform01(rng_)));
  const double phi = 2.0 * std::numbers::pi * uniform01(rng_);
  spare_ = r * std::sin(phi);
  has_spare_ = true;
  return r * std::cos(phi);
}

PointingTrial SimulatedPointer::point(double distance, double width) {
  PointingTrial t;
  t.distance = distance;
  t.width = width;
  t.start = {0.0, 0.0, 0.0};
  t.target = {distance, 0.0, 0.0};
  const double mean_mt = params_.a_s + params_.b_s_per_bit * std::log2(distance / width + 1.0);
  if (params_.lognormal_mt) {
    // ln MT ~ N(mu, s^2) with E[MT] = mean_mt and SD[MT] = mt_sd_s: s^2 = ln(1 + (sd / mean)^2),
    // mu = ln(mean) - s^2 / 2.
    const double s2 = std::log1p((params_.mt_sd_s / mean_mt) * (params_.mt_sd_s / mean_mt));
    t.movement_time_s = std::exp(std::log(mean_mt) - 0.5 * s2 + std::sqrt(s2) * normal());
  } else {
    t.movement_time_s = mean_mt + params_.mt_sd_s * normal();
  }
  const double sigma = params_.spread * width / kEffectiveWidthFactor;
  const double dx = sigma * normal();
  const double lateral = params_.lateral ? sigma * normal() : 0.0;
  t.end = {distance + dx, lateral, 0.0};
  t.hit = std::abs(dx) <= 0.5 * width;
  return t;
}

std::vector<PointingTrial> simulate_design(SimulatedPointer& pointer, std::span<const double> distances,
                                           std::span<const double> widths, int trials_per_cell) {
  std::vector<PointingTrial> trials;
  for (double d : distances)
    for (double w : widths)
      for (int i = 0; i < trials_per_cell; ++i) trials.push_back(pointer.point(d, w));
  return trials;
}

}  // namespace ps::study
