// Identification statistics (study/identification.h) against closed forms, a 2x2 worked by hand,
// and the bias the Miller-Madow term exists to remove, on simulated matrices whose true
// information is known in closed form.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "study/fit.h"
#include "study/identification.h"

namespace ps::study {
namespace {

// Every stimulus named right: I = H(rows) = log2 K, exactly, by the plug-in. The Miller-Madow
// term deems every confusion possible, so it subtracts (K - 1)^2 / (2N ln 2) even here: a perfect
// diagonal of N = 10 K trials is read as "very likely near-perfect" (by hand for K = 2, N = 20:
// 1 / (40 ln 2) = 0.0360674 bits).
TEST(IdentificationTest, PerfectDiagonalCarriesLog2KBits) {
  for (int k : {2, 4, 6, 8}) {
    ConfusionMatrix m(k, k);
    for (int i = 0; i < k; ++i) m.add(i, i, 10);
    const IdentificationStats s = identification_stats(m);
    EXPECT_DOUBLE_EQ(s.percent_correct, 100.0);
    EXPECT_NEAR(s.information_bits, std::log2(k), 1e-12);
    EXPECT_NEAR(s.miller_madow_bits, -(k - 1) * (k - 1) / (2.0 * 10 * k * std::numbers::ln2), 1e-15);
    EXPECT_NEAR(s.corrected_bits, std::log2(k) + s.miller_madow_bits, 1e-12);
    EXPECT_NEAR(std::exp2(s.corrected_bits), s.distinguishable, 1e-9);
    if (k == 2) {
      EXPECT_NEAR(s.miller_madow_bits, -0.0360674, 1e-7);
    }
  }
}

// Answers independent of the stimulus: I = 0, and the corrected value stays at 0.
TEST(IdentificationTest, UniformMatrixCarriesNothing) {
  ConfusionMatrix m(5, 5);
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) m.add(i, j, 4);
  const IdentificationStats s = identification_stats(m);
  EXPECT_NEAR(s.information_bits, 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(s.percent_correct, 20.0);
  EXPECT_NEAR(s.miller_madow_bits, -16.0 / (2.0 * 100 * std::numbers::ln2), 1e-15);  // -(5 - 1)(5 - 1)
  EXPECT_EQ(s.corrected_bits, 0.0);
  EXPECT_EQ(s.distinguishable, 1.0);
}

// [[8, 2], [3, 7]], N = 20; rows 10, 10; columns 11, 9. By hand, sum p log2(p / (p_row p_col)):
//   0.40 log2(0.40 / 0.275) = +0.2162273   0.10 log2(0.10 / 0.225) = -0.1169925
//   0.15 log2(0.15 / 0.275) = -0.1311704   0.35 log2(0.35 / 0.225) = +0.2231006
// I = 0.1911650 bits. Miller-Madow: (2 + 2 - 4 - 1) / (2 x 20 x ln 2) = -0.0360674; corrected
// 0.1550976; percent correct 75.
TEST(IdentificationTest, TwoByTwoByHand) {
  const ConfusionMatrix m({{8, 2}, {3, 7}});
  const IdentificationStats s = identification_stats(m);
  EXPECT_EQ(s.trials, 20);
  EXPECT_DOUBLE_EQ(s.percent_correct, 75.0);
  EXPECT_NEAR(s.information_bits, 0.1911650, 1e-7);
  EXPECT_NEAR(s.miller_madow_bits, -0.0360674, 1e-7);
  EXPECT_NEAR(s.corrected_bits, 0.1550976, 1e-7);
  EXPECT_NEAR(s.distinguishable, std::exp2(0.1550976), 1e-6);
}

// A symmetric channel: K = 6 textures, each named right with p = 0.6, else one of the other five
// at random. Its information in closed form (Shannon): log2 K + p log2 p + (1 - p) log2((1 - p) /
// (K - 1)) = 0.6852 bits. 400 simulated participants of 10 trials per texture (N = 60): the
// plug-in's mean over-estimates (measured +0.375 bits; Miller's estimate (K - 1)^2 / (2N ln 2) =
// 0.30); the corrected mean is nearer the truth by at least half that bias. (Counting only the
// occupied cells, the other reading of Miller-Madow, left +0.23 bits of it: it fails this test.)
TEST(IdentificationTest, MillerMadowRemovesMostOfTheSmallSampleBias) {
  constexpr int kK = 6, kPerStimulus = 10, kRuns = 400;
  const double p = 0.6;
  const double truth = std::log2(kK) + p * std::log2(p) + (1 - p) * std::log2((1 - p) / (kK - 1));
  std::mt19937_64 rng(2024);
  double plug_in = 0.0, corrected = 0.0;
  for (int run = 0; run < kRuns; ++run) {
    ConfusionMatrix m(kK, kK);
    for (int i = 0; i < kK; ++i)
      for (int t = 0; t < kPerStimulus; ++t) {
        const double u = uniform01(rng);
        const int wrong = static_cast<int>((u - p) / (1 - p) * (kK - 1));  // 0..4 when u >= p
        m.add(i, u < p ? i : (i + 1 + wrong) % kK);
      }
    const IdentificationStats s = identification_stats(m);
    plug_in += s.information_bits / kRuns;
    corrected += s.corrected_bits / kRuns;
  }
  std::printf("true %.4f bits; plug-in mean %.4f, Miller-Madow mean %.4f\n", truth, plug_in, corrected);
  const double bias = plug_in - truth;
  EXPECT_GT(bias, 0.1);
  EXPECT_LT(std::abs(corrected - truth), 0.5 * bias);
}

}  // namespace
}  // namespace ps::study
