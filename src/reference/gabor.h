// Sparse-convolution Gabor noise (thesis §4.3.1; Lagae et al. 2009), double-precision CPU twin
// of glsl/lib/gabor.glsl. The random decisions (cell seeds, LCG draws, impulse counts) are bit-
// identical to the shader; only the kernel sums are evaluated in double.
//
// Definition (units: mm):
//   cell size C = kernel_periods * lambda_max * sqrt(-ln truncation)  (= the largest truncation
//   radius, so the 3x3 cells around a point hold every kernel that reaches it).
//   Per cell: LCG state from the cell index and seed; density n ~ U[n_min, n_max] impulses per
//   kernel footprint; count = min(cap, floor(n / pi + u)) (expected n/pi per C x C cell; a
//   stratified count instead of Lagae's Poisson: the mean and variance of the noise depend only
//   on the expected count because the random phases make cross terms vanish).
//   Per impulse, in this order: x, y ~ U[0,C); A ~ U[a_min,a_max]; lambda ~ U[lmin,lmax];
//   theta ~ U[tmin,tmax]; psi ~ U[0, 2pi).
//   Stratified strategy (GaborParams::Strategy::kStratified): count = min(cap, K) fixed, no
//   density draws; impulse k sits in stratum (k mod g, k div g) of a g x g grid over the
//   cell, g = ceil(sqrt(K)), jittered by the same x, y draws; same A, lambda, theta, psi draws.
//   Kernel: A exp(-r^2/W^2) cos(2pi (dx cos(theta) + dy sin(theta)) / lambda + psi),
//   W = kernel_periods * lambda, cut to 0 where exp(-r^2/W^2) < truncation.
#pragma once

#include <cstdint>

#include "scene/scene.h"

namespace ps {

inline constexpr std::uint32_t kLcgMultiplier = 3039177861u;  // thesis §4.5.2, Lagae et al.

// Derived per-material constants shared by the shader uniforms and the reference.
struct GaborSetup {
  double cell_mm = 1.0;
  double trunc_factor = 3.0;  // -ln(truncation): kernel cut at r^2 < W^2 * trunc_factor
  double sigma_unit = 1.0;    // analytic std-dev of the noise with A == 1 (see gabor.cpp)
  int max_impulses = 64;
  // Stratified strategy: this many impulses in every cell (0 = naive random count), one per
  // stratum of a g x g grid, g = ceil(sqrt(count)).
  int stratified_count = 0;
};

GaborSetup make_gabor_setup(const GaborParams& g);

std::uint32_t gabor_cell_seed(int cx, int cy, std::uint32_t seed);
// One LCG step, then the new state mapped to [0, 1] in float (as the shader does).
float lcg_uniform(std::uint32_t& state);

// Raw noise value at (u, v) in mm (A included, not normalised).
double gabor_noise(const GaborParams& g, const GaborSetup& s, std::uint32_t seed, double u,
                   double v);

// The same impulses with untruncated kernels (5x5 cells: kernels are still cut where
// exp(-r^2/W^2) < truncation^4, i.e. below 6e-6 A at truncation 0.05): the ideal noise that
// the truncation approximates, for measuring the truncation error.
double gabor_noise_untruncated(const GaborParams& g, const GaborSetup& s, std::uint32_t seed,
                               double u, double v);

// Smallest |r - W sqrt(-ln truncation)| (mm) over the kernels evaluated at (u, v): how close
// the point lies to a truncation circle, where the noise jumps by up to truncation * |A|. Tests
// use it to tell float32 position rounding across a cut from real errors.
double gabor_truncation_margin(const GaborParams& g, const GaborSetup& s, std::uint32_t seed,
                               double u, double v);

// Number of impulses generated for one cell (for tests of the count rule and the cap).
int gabor_cell_impulse_count(const GaborParams& g, const GaborSetup& s, std::uint32_t seed,
                             int cx, int cy);

}  // namespace ps
