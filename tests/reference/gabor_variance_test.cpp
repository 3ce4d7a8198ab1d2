// The Gabor noise's normalisation (no GL): the CPU twin's measured variance over sigma_unit^2
// is 1 at every density the scene format allows (n up to 1e4), cap or no cap.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "reference/gabor.h"

namespace ps {
namespace {

struct Moments {
  double m2 = 0.0, m4 = 0.0;
  int n = 0;
};

// f at points >= 2 cells apart (a grid of 2.5 C, each point jittered by up to 0.5 C): no kernel
// reaches two of them (its radius is at most C), so the values are independent.
Moments measure(const GaborParams& g, const GaborSetup& s, int points_per_seed) {
  Moments m;
  const int side = static_cast<int>(std::ceil(std::sqrt(points_per_seed)));
  for (const std::uint32_t seed : {1u, 2u, 77u, 4000000000u}) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> jitter(0.0, 0.5 * s.cell_mm);
    for (int k = 0; k < side * side; ++k) {
      const double u = (k % side - side / 2) * 2.5 * s.cell_mm + jitter(rng);
      const double v = (k / side - side / 2) * 2.5 * s.cell_mm + jitter(rng);
      const double f = gabor_noise(g, s, seed, u, v) / s.sigma_unit;
      m.m2 += f * f, m.m4 += f * f * f * f, ++m.n;
    }
  }
  m.m2 /= m.n, m.m4 /= m.n;
  return m;
}

struct Density {
  double n_min, n_max;
  int cap;
  int stratified = 0;  // > 0: the stratified strategy with this many impulses per cell
};

TEST(GaborVarianceTest, SigmaUnitIsTheMeasuredStandardDeviationAtEveryDensity) {
  // From sparse (0.3 impulses per cell) through the cap (64 = n 201) to the format's maximum;
  // ranges that straddle the cap; another cap; the stratified count, above the cap too.
  const Density cases[] = {{1, 1, 64},        {5, 15, 64},      {20, 30, 64},   {100, 180, 64},
                           {150, 250, 64},    {400, 400, 64},   {1000, 1000, 64}, {0, 10000, 64},
                           {10000, 10000, 64}, {20, 30, 16},    {40, 60, 16},   {400, 400, 16},
                           {10000, 10000, 16}, {400, 400, 256}, {0, 0, 64, 10}, {0, 0, 16, 100}};
  for (const Density& d : cases) {
    GaborParams g;
    g.lambda_min_mm = 0.5;
    g.lambda_max_mm = 1.0;
    g.n_min = d.n_min;
    g.n_max = d.n_max;
    g.max_impulses_per_cell = d.cap;
    if (d.stratified > 0) {
      g.strategy = GaborParams::Strategy::kStratified;
      g.stratified_impulses = d.stratified;
    }
    const GaborSetup s = make_gabor_setup(g);
    const Moments m = measure(g, s, 2500);
    // The variance estimate m2 of N independent values has relative standard deviation
    // sqrt((kurtosis - 1) / N) (sqrt(2 / N) = 1.4 % for a Gaussian at N = 10^4; the sparse
    // densities are far from Gaussian, hence the measured kurtosis): 4 of them.
    const double kurtosis = m.m4 / (m.m2 * m.m2), bound = 4.0 * std::sqrt((kurtosis - 1.0) / m.n);
    std::printf("n [%g, %g] cap %d%s: E[count] %.3f, variance / sigma_unit^2 = %.4f (bound %.4f, kurtosis %.2f)\n",
                d.n_min, d.n_max, d.cap, d.stratified > 0 ? " stratified" : "", expected_cell_count(g, s), m.m2,
                bound, kurtosis);
    EXPECT_NEAR(m.m2, 1.0, bound) << "n [" << d.n_min << ", " << d.n_max << "] cap " << d.cap;
  }
}

TEST(GaborVarianceTest, ExpectedCountIsTheMeanOfTheDrawnCounts) {
  // E[min(count, cap)] against the mean count drawn over 10^5 cells, within 4 standard
  // deviations of that mean (the counts' own spread over sqrt(10^5)).
  for (const Density& d : {Density{0, 300, 64}, Density{150, 250, 64}, Density{10, 90, 16}, Density{7, 7, 64}}) {
    GaborParams g;
    g.n_min = d.n_min;
    g.n_max = d.n_max;
    g.max_impulses_per_cell = d.cap;
    const GaborSetup s = make_gabor_setup(g);
    double sum = 0.0, sum2 = 0.0;
    constexpr int kCells = 100000;
    for (int k = 0; k < kCells; ++k) {
      const double c = gabor_cell_impulse_count(g, s, 9, k % 400, k / 400);
      sum += c, sum2 += c * c;
    }
    const double mean = sum / kCells, sd = std::sqrt(sum2 / kCells - mean * mean);
    EXPECT_NEAR(mean, expected_cell_count(g, s), 4.0 * sd / std::sqrt(kCells) + 1e-9)
        << "n [" << d.n_min << ", " << d.n_max << "] cap " << d.cap;
  }
}

}  // namespace
}  // namespace ps
