// Gabor cell seeds (no GL): every cell of a large block gets its own LCG state for every
// material seed, and the CPU twin's texture shows no correlation between cells c and -c or
// between translated cells.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "reference/gabor.h"

namespace ps {
namespace {

// The one key whose hash is 0 is seed + kGaborSeedOffset (fmix32(key) == fmix32(seed + offset));
// this seed puts it at key 0x100, the cell (256, 0), inside the block tested below.
constexpr std::uint32_t kSeedWithZeroCellInBlock = 0x100u - kGaborSeedOffset;

TEST(GaborSeedTest, EveryCellOfTheBlockHasItsOwnSeed) {
  // [-1024, 1024)^2: 4,194,304 cells. A good but non-injective 32-bit hash would repeat about
  // n^2 / 2^33 = 2048 of them; the keyed bijection repeats none.
  for (const std::uint32_t seed : {0u, 1u, 2654435769u, 0xffffffffu, kSeedWithZeroCellInBlock}) {
    std::vector<std::uint32_t> states;
    states.reserve(2048 * 2048);
    for (int cy = -1024; cy < 1024; ++cy)
      for (int cx = -1024; cx < 1024; ++cx) states.push_back(gabor_cell_seed(cx, cy, seed));
    std::sort(states.begin(), states.end());
    EXPECT_NE(states.front(), 0u) << "seed " << seed << ": an LCG started at 0 stays 0";
    const auto repeats = states.end() - std::unique(states.begin(), states.end());
    EXPECT_EQ(repeats, 0) << "seed " << seed << ": cells sharing a state";
  }
}

TEST(GaborSeedTest, MirroredAndTranslatedCellsDiffer) {
  // The old hash (cx 73856093 ^ cy 19349663 ^ seed 83492791) gave both of these the same seed.
  EXPECT_NE(gabor_cell_seed(1, 1, 1), gabor_cell_seed(-1, -1, 1));
  EXPECT_NE(gabor_cell_seed(4, 12, 7), gabor_cell_seed(-4, -12, 7));
  EXPECT_NE(gabor_cell_seed(0, 0, 1), gabor_cell_seed(1, 0, 1));
  EXPECT_NE(gabor_cell_seed(0, 0, 1), gabor_cell_seed(0, 1, 1));
  EXPECT_NE(gabor_cell_seed(-1, 0, 1), gabor_cell_seed(1, 0, 1));
  // Other material seeds: other states for the same cell.
  EXPECT_NE(gabor_cell_seed(3, 5, 1), gabor_cell_seed(3, 5, 2));
}

TEST(GaborSeedTest, TheZeroStateTakesTheCellHalfAPeriodAway) {
  const std::uint32_t seed = kSeedWithZeroCellInBlock;
  ASSERT_EQ(fmix32(fmix32(0x100u) ^ fmix32(seed + kGaborSeedOffset)), 0u);  // the premise: key 0x100
  EXPECT_NE(gabor_cell_seed(256, 0, seed), 0u);
  EXPECT_EQ(gabor_cell_seed(256, 0, seed), gabor_cell_seed(256 + 32768, 32768, seed));
  EXPECT_EQ(gabor_cell_seed(256, 0, seed), gabor_cell_seed(256 - 32768, -32768, seed));
}

TEST(GaborSeedTest, TheTextureRepeatsAfter65536Cells) {
  // The documented period (the key keeps 16 bits per axis); half of it is no repeat.
  GaborParams g;
  const GaborSetup s = make_gabor_setup(g);
  const double period = 65536.0 * s.cell_mm;
  for (const double u : {0.3, -17.9, 123.4}) {
    const double f = gabor_noise(g, s, 1, u, 2.1);
    // The cell and its offset are recomputed from u + period: ~1e-16 relative of 6.5e5 mm.
    EXPECT_NEAR(gabor_noise(g, s, 1, u + period, 2.1), f, 1e-6);
    EXPECT_NEAR(gabor_noise(g, s, 1, u, 2.1 - period), f, 1e-6);
  }
  EXPECT_NE(gabor_cell_seed(5, 7, 1), gabor_cell_seed(5 + 32768, 7, 1));
}

// Correlation of the texture at pairs (p, q): sum f(p) f(q) / sqrt(sum f(p)^2 sum f(q)^2) (the
// noise has mean 0: random phases).
struct PairCorrelation {
  double sum_pq = 0.0, sum_pp = 0.0, sum_qq = 0.0;
  int n = 0;
  void add(double fp, double fq) { sum_pq += fp * fq, sum_pp += fp * fp, sum_qq += fq * fq, ++n; }
  double r() const { return sum_pq / std::sqrt(sum_pp * sum_qq); }
};

GaborParams correlation_material() {  // the bench scene's material (src/app/bench/bench_sweep.cpp)
  GaborParams g;
  g.lambda_min_mm = 0.8;
  g.lambda_max_mm = 2.0;
  g.theta_max_rad = 1.0;
  g.n_min = 20;
  g.n_max = 30;
  return g;
}

constexpr int kPairs = 10000;
// Independent values: r has mean 0 and standard deviation 1 / sqrt(N) (each term f(p) f(q) has
// variance E[f^2] E[g^2]); the pairs' points scatter over >= 128 x 128 cells and rarely share a
// kernel, so 4 standard deviations leave room without hiding a real correlation. The former
// hash (cx 73856093 ^ cy 19349663 ^ seed 83492791) gave r(c, -c) = 0.21 here (0.68 over the
// 33 % of cells whose mirror shared their seed) and repeated 700,238 of the 4,194,304 states
// in [-1024, 1024)^2.
const double kIndependentR = 4.0 / std::sqrt(static_cast<double>(kPairs));

TEST(GaborSeedTest, CellsAndTheirMirrorsAreUncorrelated) {
  // p in cell c at offset o; q = p - 2 c C lies in cell -c at the same offset: the same texture
  // if the two cells shared a seed. Cells in [-64, 64)^2 (around the origin, where scenes put
  // their surfaces), at least 2 cells from the origin so that p and q share no kernel.
  const GaborParams g = correlation_material();
  const GaborSetup s = make_gabor_setup(g);
  std::mt19937 rng(30);
  std::uniform_int_distribution<int> cell(-64, 63);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  PairCorrelation mirror, unrelated;
  while (mirror.n < kPairs) {
    const int cx = cell(rng), cy = cell(rng);
    if (std::max(std::abs(cx), std::abs(cy)) < 2) continue;
    const double ou = unit(rng) * s.cell_mm, ov = unit(rng) * s.cell_mm;
    const double fp = gabor_noise(g, s, 1, cx * s.cell_mm + ou, cy * s.cell_mm + ov);
    mirror.add(fp, gabor_noise(g, s, 1, -cx * s.cell_mm + ou, -cy * s.cell_mm + ov));
    // The same p against a point of an unrelated cell.
    const double qu = (cell(rng) + unit(rng)) * s.cell_mm, qv = (cell(rng) + unit(rng)) * s.cell_mm;
    unrelated.add(fp, gabor_noise(g, s, 1, qu + 200.0 * s.cell_mm, qv));
  }
  std::printf("r(c, -c) = %.4f, r(unrelated) = %.4f over %d pairs (bound %.3f)\n", mirror.r(), unrelated.r(),
              kPairs, kIndependentR);
  EXPECT_LT(std::abs(unrelated.r()), kIndependentR);
  EXPECT_LT(std::abs(mirror.r()), kIndependentR);
}

TEST(GaborSeedTest, TranslatedCellsAreUncorrelated) {
  // p anywhere in [-1024, 1024)^2 cells against p + t C: for a structured hash some t maps
  // many cells onto cells with related states (a linear hash: powers of two).
  const GaborParams g = correlation_material();
  const GaborSetup s = make_gabor_setup(g);
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> pos(-1024.0, 1024.0);
  const int shifts[][2] = {{2, 0}, {0, 2}, {3, -5}, {64, 0}, {0, 1024}, {-256, 256}, {1000, 7}, {32768, 0}};
  for (const auto& t : shifts) {
    PairCorrelation c;
    while (c.n < kPairs / 4) {  // 2500 pairs per shift: bound 4 / sqrt(2500)
      const double u = pos(rng) * s.cell_mm, v = pos(rng) * s.cell_mm;
      c.add(gabor_noise(g, s, 7, u, v), gabor_noise(g, s, 7, u + t[0] * s.cell_mm, v + t[1] * s.cell_mm));
    }
    const double bound = 4.0 / std::sqrt(static_cast<double>(c.n));
    std::printf("r(c, c + (%d, %d)) = %.4f (bound %.3f)\n", t[0], t[1], c.r(), bound);
    EXPECT_LT(std::abs(c.r()), bound) << "shift " << t[0] << ", " << t[1];
  }
}

}  // namespace
}  // namespace ps
