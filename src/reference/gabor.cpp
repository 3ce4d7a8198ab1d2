#include "reference/gabor.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace ps {

namespace {

// Variance of the sparse-convolution process for A == 1 (Lagae et al. 2009, eq. for random
// phase): impulses per mm^2 times the integral of the squared kernel. With random phase the
// cos^2 averages to 1/2 exactly, and the Gaussian squared integrates to pi W^2 / 2, so
//   sigma^2 = (n_mean / (pi C^2)) * (1/2) * (pi / 2) E[W^2] = n_mean E[W^2] / (4 C^2).
// Truncation at exp(-r^2/W^2) = t removes a fraction t^2 of that integral (ignored: 0.25 %
// at t = 0.05).
double unit_sigma(const GaborParams& g, double cell_mm, int stratified_count) {
  const double a = g.lambda_min_mm, b = g.lambda_max_mm;
  const double e_lambda2 = (a * a + a * b + b * b) / 3.0;  // lambda ~ U[a, b]
  const double e_w2 = g.kernel_periods * g.kernel_periods * e_lambda2;
  // Stratified: K impulses per cell is the density of n = K pi impulses per kernel footprint.
  const double n_mean = stratified_count > 0 ? stratified_count * std::numbers::pi : 0.5 * (g.n_min + g.n_max);
  const double var = n_mean * e_w2 / (4.0 * cell_mm * cell_mm);
  return var > 0.0 ? std::sqrt(var) : 1.0;
}

}  // namespace

GaborSetup make_gabor_setup(const GaborParams& g) {
  GaborSetup s;
  s.trunc_factor = -std::log(std::clamp(g.truncation, 1e-12, 0.999999));
  const double lambda_max = std::max(g.lambda_min_mm, g.lambda_max_mm);
  s.cell_mm = std::max(1e-6, g.kernel_periods * lambda_max * std::sqrt(s.trunc_factor));
  s.max_impulses = std::max(0, g.max_impulses_per_cell);
  if (g.strategy == GaborParams::Strategy::kStratified)
    s.stratified_count = std::clamp(g.stratified_impulses, 1, std::max(1, s.max_impulses));
  s.sigma_unit = unit_sigma(g, s.cell_mm, s.stratified_count);
  return s;
}

std::uint32_t gabor_cell_seed(int cx, int cy, std::uint32_t seed) {
  std::uint32_t h = static_cast<std::uint32_t>(cx) * 73856093u ^
                    static_cast<std::uint32_t>(cy) * 19349663u ^ seed * 83492791u;
  return h == 0u ? 1u : h;
}

float lcg_uniform(std::uint32_t& state) {
  state *= kLcgMultiplier;  // mod 2^32 by unsigned wrap-around
  return static_cast<float>(state) * (1.0f / 4294967296.0f);
}

namespace {

int cell_count(const GaborParams& g, const GaborSetup& s, std::uint32_t& r) {
  if (s.stratified_count > 0) return std::min(s.stratified_count, s.max_impulses);
  // Same float operations as the shader (mix = a + (b - a) * t) so counts match bit for bit.
  const float n_min = static_cast<float>(g.n_min), n_max = static_cast<float>(g.n_max);
  const float n = n_min + (n_max - n_min) * lcg_uniform(r);
  const float expected = n * static_cast<float>(1.0 / std::numbers::pi);
  const int count = static_cast<int>(std::floor(expected + lcg_uniform(r)));
  return std::clamp(count, 0, s.max_impulses);
}

double cell_sum(const GaborParams& g, const GaborSetup& s, std::uint32_t seed, int cx, int cy,
                double px, double py, double* margin = nullptr, double trunc_factor = 0.0) {
  if (trunc_factor <= 0.0) trunc_factor = s.trunc_factor;
  std::uint32_t r = gabor_cell_seed(cx, cy, seed);
  const int count = cell_count(g, s, r);
  // Naive: one stratum (the whole cell); stratified: a g x g grid. Same float ops as the shader.
  const int grid = s.stratified_count > 0 ? static_cast<int>(std::ceil(std::sqrt(static_cast<float>(s.stratified_count)))) : 1;
  const float inv_grid = 1.0f / static_cast<float>(grid);
  double sum = 0.0;
  for (int k = 0; k < count; ++k) {
    const float jx = (static_cast<float>(k % grid) + lcg_uniform(r)) * inv_grid;
    const float jy = (static_cast<float>((k / grid) % grid) + lcg_uniform(r)) * inv_grid;
    const double dx = px - jx * s.cell_mm;
    const double dy = py - jy * s.cell_mm;
    const double amp = std::lerp(g.a_min, g.a_max, static_cast<double>(lcg_uniform(r)));
    const double lambda = std::lerp(g.lambda_min_mm, g.lambda_max_mm, static_cast<double>(lcg_uniform(r)));
    const double theta = std::lerp(g.theta_min_rad, g.theta_max_rad, static_cast<double>(lcg_uniform(r)));
    const double psi = 2.0 * std::numbers::pi * lcg_uniform(r);
    const double w = g.kernel_periods * lambda;
    const double r2 = dx * dx + dy * dy;
    if (margin && w > 0.0)
      *margin = std::min(*margin, std::abs(std::sqrt(r2) - w * std::sqrt(s.trunc_factor)));
    if (w <= 0.0 || r2 >= w * w * trunc_factor) continue;
    const double phase = 2.0 * std::numbers::pi * (dx * std::cos(theta) + dy * std::sin(theta)) / lambda;
    sum += amp * std::exp(-r2 / (w * w)) * std::cos(phase + psi);
  }
  return sum;
}

}  // namespace

double gabor_noise(const GaborParams& g, const GaborSetup& s, std::uint32_t seed, double u,
                   double v) {
  const double fx = u / s.cell_mm, fy = v / s.cell_mm;
  const int cx = static_cast<int>(std::floor(fx)), cy = static_cast<int>(std::floor(fy));
  const double ox = (fx - cx) * s.cell_mm, oy = (fy - cy) * s.cell_mm;  // p relative to its cell
  double sum = 0.0;
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i)
      sum += cell_sum(g, s, seed, cx + i, cy + j, ox - i * s.cell_mm, oy - j * s.cell_mm);
  return sum;
}

double gabor_noise_untruncated(const GaborParams& g, const GaborSetup& s, std::uint32_t seed,
                               double u, double v) {
  const double fx = u / s.cell_mm, fy = v / s.cell_mm;
  const int cx = static_cast<int>(std::floor(fx)), cy = static_cast<int>(std::floor(fy));
  const double ox = (fx - cx) * s.cell_mm, oy = (fy - cy) * s.cell_mm;
  double sum = 0.0;
  for (int j = -2; j <= 2; ++j)
    for (int i = -2; i <= 2; ++i)  // 2 cells = 2 W sqrt(-ln t): radius at which exp = t^4
      sum += cell_sum(g, s, seed, cx + i, cy + j, ox - i * s.cell_mm, oy - j * s.cell_mm, nullptr,
                      4.0 * s.trunc_factor);
  return sum;
}

double gabor_truncation_margin(const GaborParams& g, const GaborSetup& s, std::uint32_t seed,
                               double u, double v) {
  const double fx = u / s.cell_mm, fy = v / s.cell_mm;
  const int cx = static_cast<int>(std::floor(fx)), cy = static_cast<int>(std::floor(fy));
  const double ox = (fx - cx) * s.cell_mm, oy = (fy - cy) * s.cell_mm;
  double margin = std::numeric_limits<double>::infinity();
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i)
      cell_sum(g, s, seed, cx + i, cy + j, ox - i * s.cell_mm, oy - j * s.cell_mm, &margin);
  return margin;
}

int gabor_cell_impulse_count(const GaborParams& g, const GaborSetup& s, std::uint32_t seed,
                             int cx, int cy) {
  std::uint32_t r = gabor_cell_seed(cx, cy, seed);
  return cell_count(g, s, r);
}

}  // namespace ps
