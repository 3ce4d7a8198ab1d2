// A simulated pointing participant with a known Fitts law (docs/study.md, "Targeting statistics
// (Fitts, ISO 9241-9)"): what the tests recover with study/fitts.h. Movement times follow
// MT = a + b log2(D / W + 1) plus noise; end points scatter normally about the target centre along
// the task axis with the SD that makes the expected effective width a chosen multiple of W.
#pragma once

#include <cstdint>
#include <random>
#include <span>
#include <vector>

#include "study/fitts.h"

namespace ps::study {

struct PointerParams {
  double a_s = 0.2;           // Fitts intercept a, seconds
  double b_s_per_bit = 0.15;  // Fitts slope b, seconds per bit of the nominal ID
  double mt_sd_s = 0.05;      // SD of a trial's movement time about a + b ID, seconds
  // The noise's shape: Gaussian (additive, the same SD at every ID: what ordinary least squares
  // assumes), or lognormal with the same mean and SD (multiplicative, always positive).
  bool lognormal_mt = false;
  // The end points' SD along the axis is spread W / 4.133, so the expected We is spread W:
  // spread 1 aims as ISO 9241-9 assumes (about 3.9 % misses: P(|z| > 4.133 / 2)), < 1 more
  // carefully, > 1 faster and sloppier.
  double spread = 1.0;
  bool lateral = true;  // scatter sideways too, with the same SD (the projection must ignore it)
};

class SimulatedPointer {
 public:
  SimulatedPointer(PointerParams params, std::uint64_t seed);
  // One discrete trial along +x: start at the origin, target centre at (D, 0, 0). A hit is an end
  // point within W / 2 of the centre along the axis (a strip target, as in Fitts' 1D task).
  PointingTrial point(double distance, double width);
  const PointerParams& params() const { return params_; }

 private:
  double normal();  // standard normal, Box-Muller over uniform01 (study/fit.h)
  PointerParams params_;
  std::mt19937_64 rng_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

// A block of trials: every (D, W) of the design `trials_per_cell` times, cell after cell (the
// order does not matter to a simulated pointer that neither learns nor tires).
std::vector<PointingTrial> simulate_design(SimulatedPointer& pointer, std::span<const double> distances,
                                           std::span<const double> widths, int trials_per_cell);

}  // namespace ps::study
