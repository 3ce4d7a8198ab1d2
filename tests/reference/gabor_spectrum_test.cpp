// Spectrum and statistics of the CPU Gabor reference (thesis §4.3.1): the texture's power sits
// at frequency 1/lambda in direction theta; a theta range of pi makes it isotropic; its mean
// and variance are the analytic ones (sigma_unit). Tolerances follow the measured scatter of a
// finite image (docs: relative frequency sd ~ 0.36 / P and angle sd ~ 20 deg / P, P = wave
// periods across the image). Images are sampled at 4 pixels per period, so a 256^2 image holds
// P = 64 periods: the same statistics as a 1024^2 image at 16 pixels per period.
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "reference/gabor.h"

namespace ps {
namespace {

using Cplx = std::complex<double>;
constexpr int kSize = 256;            // power of two for the radix-2 FFT
constexpr double kPixelsPerPeriod = 4.0;
constexpr double kPi = std::numbers::pi;

// In-place iterative radix-2 FFT of length n (power of two), stride s.
void fft(Cplx* a, int n, int s) {
  for (int i = 1, j = 0; i < n; ++i) {
    int bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) std::swap(a[i * s], a[j * s]);
  }
  for (int len = 2; len <= n; len <<= 1) {
    const Cplx w(std::cos(-2 * kPi / len), std::sin(-2 * kPi / len));
    for (int i = 0; i < n; i += len) {
      Cplx wk(1.0);
      for (int k = 0; k < len / 2; ++k, wk *= w) {
        const Cplx u = a[(i + k) * s], v = a[(i + k + len / 2) * s] * wk;
        a[(i + k) * s] = u + v;
        a[(i + k + len / 2) * s] = u - v;
      }
    }
  }
}

// Hann-windowed periodogram of the noise sampled at `pixel_mm` spacing, accumulated into `power`.
void add_periodogram(const GaborParams& g, std::uint32_t seed, double pixel_mm, std::vector<double>& power) {
  const GaborSetup s = make_gabor_setup(g);
  std::vector<Cplx> img(kSize * kSize);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const double hann = 0.25 * (1 - std::cos(2 * kPi * x / kSize)) * (1 - std::cos(2 * kPi * y / kSize));
      img[y * kSize + x] = hann * gabor_noise(g, s, seed, x * pixel_mm, y * pixel_mm);
    }
  for (int y = 0; y < kSize; ++y) fft(&img[y * kSize], kSize, 1);
  for (int x = 0; x < kSize; ++x) fft(&img[x], kSize, kSize);
  for (int i = 0; i < kSize * kSize; ++i) power[i] += std::norm(img[i]);
}

// Signed frequency of FFT bin k in cycles per pixel.
double bin_freq(int k) { return (k < kSize / 2 ? k : k - kSize) / static_cast<double>(kSize); }

struct Centroid {
  double freq = 0.0;   // cycles per pixel
  double angle = 0.0;  // rad
};

// Power-weighted centroid over the half-plane around `theta` (the peak's half of the spectrum).
Centroid half_plane_centroid(const std::vector<double>& power, double theta) {
  double fx = 0, fy = 0, total = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const double u = bin_freq(x), v = bin_freq(y);
      if (u * std::cos(theta) + v * std::sin(theta) <= 0.0) continue;
      const double p = power[y * kSize + x];
      fx += p * u;
      fy += p * v;
      total += p;
    }
  return {std::hypot(fx, fy) / total, std::atan2(fy, fx)};
}

GaborParams material(double lambda_mm, double theta_min, double theta_max) {
  GaborParams g;
  g.lambda_min_mm = g.lambda_max_mm = lambda_mm;
  g.theta_min_rad = theta_min;
  g.theta_max_rad = theta_max;
  return g;
}

TEST(GaborSpectrumTest, AnisotropicPeakAtWavelengthAndOrientation) {
  // P = 64 periods across: sd 0.56 % / 0.31 deg per image; 2 seeds averaged give ~0.4 % / 0.22
  // deg, so 2 % / 1 deg is about 4.5 sd.
  for (const double theta : {0.0, 1.3, 2.4}) {
    const GaborParams g = material(0.5, theta, theta);
    std::vector<double> power(kSize * kSize, 0.0);
    for (std::uint32_t seed : {1u, 2u}) add_periodogram(g, seed, 0.5 / kPixelsPerPeriod, power);
    const Centroid c = half_plane_centroid(power, theta);
    EXPECT_NEAR(c.freq * kPixelsPerPeriod, 1.0, 0.02) << "theta " << theta;
    double da = std::remainder(c.angle - theta, 2 * kPi);
    EXPECT_NEAR(da * 180 / kPi, 0.0, 1.0) << "theta " << theta;
  }
}

// Fraction of the power of the frequency ring [0.5, 1.5] / lambda in each of 4 orientation
// sectors of 45 deg over [0, pi) (the other half-plane mirrors it).
std::vector<double> sector_fractions(const std::vector<double>& power) {
  std::vector<double> sector(4, 0.0);
  double total = 0.0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const double u = bin_freq(x), v = bin_freq(y), f = std::hypot(u, v) * kPixelsPerPeriod;
      if (f < 0.5 || f > 1.5) continue;
      double a = std::atan2(v, u);
      if (a < 0) a += kPi;
      const int k = std::min(3, static_cast<int>(a / (kPi / 4)));
      sector[k] += power[y * kSize + x];
      total += power[y * kSize + x];
    }
  for (double& s : sector) s /= total;
  return sector;
}

TEST(GaborSpectrumTest, FullThetaRangeIsIsotropic) {
  // ~500 Hann-correlated bins per sector and image: sd ~ 8 % of a sector's share per image,
  // ~4 % over 4 seeds. 15 % allows ~4 sd; an anisotropic texture puts > 90 % in one sector.
  const GaborParams g = material(0.5, 0.0, kPi);
  std::vector<double> power(kSize * kSize, 0.0);
  for (std::uint32_t seed : {1u, 2u, 3u, 4u}) add_periodogram(g, seed, 0.5 / kPixelsPerPeriod, power);
  for (double share : sector_fractions(power)) EXPECT_NEAR(share / 0.25, 1.0, 0.15);
  const GaborParams aniso = material(0.5, kPi / 8, kPi / 8);  // centre of sector 0
  std::vector<double> p2(kSize * kSize, 0.0);
  add_periodogram(aniso, 1u, 0.5 / kPixelsPerPeriod, p2);
  EXPECT_GT(sector_fractions(p2)[0], 0.9);
}

// Mean and variance over 40,000 points three cells apart (independent kernels), per material.
TEST(GaborSpectrumTest, MeanAndVarianceMatchAnalytic) {
  // Independent samples of a near-Gaussian sum of ~70 kernels: sd of the variance ratio is
  // ~sqrt(2 / 40000) = 0.7 %, of the mean 0.5 % sigma. Truncation (t = 0.05) removes 0.25 % of
  // the variance the formula counts. 5 % is > 5 sd for both.
  const GaborParams mats[] = {material(0.5, 0.0, 0.0), material(0.8, 0.0, kPi)};
  GaborParams ranged = material(0.4, 0.3, 1.1);
  ranged.lambda_max_mm = 1.2;
  ranged.n_min = 10;
  ranged.n_max = 40;
  GaborParams stratified = material(0.6, 0.0, 1.0);
  stratified.strategy = GaborParams::Strategy::kStratified;
  stratified.stratified_impulses = 4;
  for (const GaborParams& g : {mats[0], mats[1], ranged, stratified}) {
    const GaborSetup s = make_gabor_setup(g);
    double sum = 0.0, sum2 = 0.0;
    const int n = 200;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const double j = 0.37 * ((x * 7 + y * 13) % 11) / 11.0;  // position inside the cell
        const double v = gabor_noise(g, s, 5, (3 * x + j) * s.cell_mm, (3 * y + 0.5 - j) * s.cell_mm);
        sum += v;
        sum2 += v * v;
      }
    const double mean = sum / (n * n), var = sum2 / (n * n) - mean * mean;
    EXPECT_NEAR(var / (s.sigma_unit * s.sigma_unit), 1.0, 0.05) << "lambda " << g.lambda_min_mm;
    EXPECT_NEAR(mean / s.sigma_unit, 0.0, 0.05);
  }
}

TEST(GaborSpectrumTest, StratifiedHasFixedCountAndTheSamePeak) {
  GaborParams g = material(0.5, 0.6, 0.6);
  g.strategy = GaborParams::Strategy::kStratified;
  g.stratified_impulses = 3;
  const GaborSetup s = make_gabor_setup(g);
  for (int c = 0; c < 50; ++c) EXPECT_EQ(gabor_cell_impulse_count(g, s, 7, c, -c), 3);
  std::vector<double> power(kSize * kSize, 0.0);
  for (std::uint32_t seed : {1u, 2u}) add_periodogram(g, seed, 0.5 / kPixelsPerPeriod, power);
  const Centroid c = half_plane_centroid(power, 0.6);
  EXPECT_NEAR(c.freq * kPixelsPerPeriod, 1.0, 0.02);  // same tolerances as the naive peak
  EXPECT_NEAR(std::remainder(c.angle - 0.6, 2 * kPi) * 180 / kPi, 0.0, 1.0);
}

}  // namespace
}  // namespace ps
