// Targeting statistics (study/fitts.h) and the simulated pointing participant
// (study/pointing_sim.h): a cell worked by hand, the same cell turned in 3D, the textbook identity
// We = W => IDe = ID, MacKenzie's published throughput example, the regression and the t
// quantiles against R, degenerate cells reported as not computable, and known Fitts laws
// recovered from simulated participants.
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "study/fitts.h"
#include "study/pointing_sim.h"

namespace ps::study {
namespace {

// Student's t against R 4.2.2's qt() and pt() (options(digits = 15)), and the 95 % column of the
// maze's table (src/maze/maze_summary.cpp, three decimals).
TEST(FittsTest, StudentTMatchesR) {
  EXPECT_NEAR(student_t_quantile(0.975, 1), 12.70620473617469, 1e-9);
  EXPECT_NEAR(student_t_quantile(0.975, 2), 4.30265272974946, 1e-10);
  EXPECT_NEAR(student_t_quantile(0.975, 4), 2.77644510519779, 1e-10);
  EXPECT_NEAR(student_t_quantile(0.975, 7), 2.36462425159278, 1e-10);
  EXPECT_NEAR(student_t_quantile(0.975, 30), 2.04227245630124, 1e-10);
  EXPECT_NEAR(student_t_quantile(0.975, 100), 1.98397151852355, 1e-10);
  EXPECT_NEAR(student_t_quantile(0.995, 3), 5.84090930973335, 1e-9);
  EXPECT_NEAR(student_t_quantile(0.9995, 1), 636.61924876879, 1e-6);
  EXPECT_NEAR(student_t_quantile(0.025, 7), -2.36462425159278, 1e-10);
  EXPECT_NEAR(student_t_cdf(2.5, 5), 0.972754950328812, 1e-12);
  EXPECT_NEAR(student_t_cdf(-1.3, 12), 0.109008585541757, 1e-12);
  EXPECT_EQ(student_t_quantile(0.5, 9), 0.0);
  const double maze[] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228};
  for (int df = 1; df <= 10; ++df) EXPECT_NEAR(student_t_quantile(0.975, df), maze[df - 1], 5e-4) << df;
  EXPECT_TRUE(std::isnan(student_t_quantile(0.975, 0)));
  EXPECT_TRUE(std::isnan(student_t_quantile(1.0, 5)));
  EXPECT_TRUE(std::isnan(student_t_quantile(0.0, 5)));
}

// Five trials at D = 100, W = 20 (mm), start at the origin, target at (100, 0), the end points at
// x = 96, 104, 100, 98, 107, so along the axis dx = -4, 4, 0, -2, 7; the fourth trial is a miss.
// By hand:
//   De   = 100 + mean dx = 100 + 5 / 5 = 101
//   SDx  = sqrt(((-5)^2 + 3^2 + (-1)^2 + (-3)^2 + 6^2) / 4) = sqrt(80 / 4) = sqrt(20) = 4.472135955
//   We   = 4.133 x 4.472135955 = 18.483337902
//   IDe  = log2(101 / 18.483337902 + 1) = log2(6.464380976) = 2.692512225 bits
//   MT   = (0.60 + 0.70 + 0.65 + 0.55 + 0.75) / 5 = 0.65 s
//   TP   = 2.692512225 / 0.65 = 4.142326500 bit/s
//   ID   = log2(100 / 20 + 1) = log2 6 = 2.584962501 bits; errors 1 / 5 = 20 %
// (the same numbers from numpy: 101.0, 4.47213595499958, 18.48333790201326, 2.692512225258544,
// 4.14232650039776).
constexpr double kHandDx[] = {-4.0, 4.0, 0.0, -2.0, 7.0};
constexpr double kHandMt[] = {0.60, 0.70, 0.65, 0.55, 0.75};
constexpr bool kHandHit[] = {true, true, true, false, true};

void expect_hand_cell(const FittsCell& c) {
  ASSERT_EQ(c.status, CellStatus::kOk) << to_string(c.status);
  EXPECT_EQ(c.trials, 5);
  EXPECT_EQ(c.misses, 1);
  EXPECT_NEAR(c.error_percent, 20.0, 1e-12);
  EXPECT_NEAR(c.id_bits, 2.584962501, 1e-9);
  EXPECT_NEAR(c.effective_distance, 101.0, 1e-9);
  EXPECT_NEAR(c.mean_dx, 1.0, 1e-9);
  EXPECT_NEAR(c.sd_x, 4.472135955, 1e-9);
  EXPECT_NEAR(c.effective_width, 18.483337902, 1e-8);
  EXPECT_NEAR(c.effective_id_bits, 2.692512225, 1e-9);
  EXPECT_NEAR(c.mean_mt_s, 0.65, 1e-12);
  EXPECT_NEAR(c.throughput_bps, 4.142326500, 1e-8);
}

TEST(FittsTest, CellWorkedByHand) {
  std::vector<PointingTrial> trials;
  for (int i = 0; i < 5; ++i) {
    PointingTrial t;
    t.distance = 100.0;
    t.width = 20.0;
    t.start = {0.0, 0.0, 0.0};
    t.target = {100.0, 0.0, 0.0};
    t.end = {100.0 + kHandDx[i], 0.0, 0.0};
    t.movement_time_s = kHandMt[i];
    t.hit = kHandHit[i];
    trials.push_back(t);
  }
  expect_hand_cell(fitts_cell(trials));
}

// The same five trials along a 3D axis u = (2, 3, 6) / 7 from (1, -2, 5), each end point pushed
// sideways by up to 9 mm along v = (3, -2, 0) / sqrt 13 and w = u x v, both perpendicular to u:
// the projection must give the hand-worked numbers unchanged.
TEST(FittsTest, ProjectionIgnoresDirectionAndSidewaysError) {
  const Point3 start{1.0, -2.0, 5.0};
  const Point3 u{2.0 / 7.0, 3.0 / 7.0, 6.0 / 7.0};
  const double s13 = std::sqrt(13.0);
  const Point3 v{3.0 / s13, -2.0 / s13, 0.0};
  const Point3 w{u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
  const double side_v[] = {3.0, -9.0, 0.5, 6.0, -2.0}, side_w[] = {-1.0, 4.0, 8.0, -7.0, 0.0};
  auto at = [&](double along, double a, double b) {
    return Point3{start.x + along * u.x + a * v.x + b * w.x, start.y + along * u.y + a * v.y + b * w.y,
                  start.z + along * u.z + a * v.z + b * w.z};
  };
  std::vector<PointingTrial> trials;
  for (int i = 0; i < 5; ++i) {
    PointingTrial t;
    t.distance = 100.0;
    t.width = 20.0;
    t.start = start;
    t.target = at(100.0, 0.0, 0.0);
    t.end = at(100.0 + kHandDx[i], side_v[i], side_w[i]);
    t.movement_time_s = kHandMt[i];
    t.hit = kHandHit[i];
    trials.push_back(t);
  }
  expect_hand_cell(fitts_cell(trials));
  // A movement that began 3 mm behind the start along the axis (and 5 sideways) is 3 mm longer.
  PointingTrial t = trials[0];
  t.began = at(-3.0, 5.0, 0.0);
  const AxisProjection p = project_on_axis(t);
  EXPECT_NEAR(p.dx, -4.0, 1e-9);
  EXPECT_NEAR(p.amplitude, 99.0, 1e-9);
}

// The textbook arithmetic (Soukoreff & MacKenzie 2004; ISO 9241-9): We = 4.133 SDx, and a cell
// whose end points have SDx = W / 4.133 about the target centre has We = W and so IDe = ID. Two
// end points at D -/+ s have SDx = s sqrt 2, so s = W / (4.133 sqrt 2).
TEST(FittsTest, EffectiveWidthEqualToWidthGivesNominalId) {
  for (double d : {64.0, 128.0, 512.0})
    for (double w : {8.0, 16.0, 48.0}) {
      const double s = w / (4.133 * std::sqrt(2.0));
      std::vector<PointingTrial> trials(2);
      for (int i = 0; i < 2; ++i) {
        trials[i].distance = d;
        trials[i].width = w;
        trials[i].target = {d, 0.0, 0.0};
        trials[i].end = {d + (i == 0 ? -s : s), 0.0, 0.0};
        trials[i].movement_time_s = 0.5;
        trials[i].hit = true;
      }
      const FittsCell c = fitts_cell(trials);
      ASSERT_TRUE(c.computable()) << to_string(c.status);
      EXPECT_NEAR(c.sd_x, w / 4.133, 1e-12 * w);
      EXPECT_NEAR(c.effective_width, 4.133 * c.sd_x, 1e-12 * w);
      EXPECT_NEAR(c.effective_width, w, 1e-12 * w);
      EXPECT_NEAR(c.effective_id_bits, std::log2(d / w + 1.0), 1e-12);
      EXPECT_NEAR(c.effective_id_bits, c.id_bits, 1e-12);
      EXPECT_NEAR(c.throughput_bps, c.id_bits / 0.5, 1e-11);
    }
}

// MacKenzie's published worked example: the documentation of his Throughput class (FittsLawSoftware,
// York University, 2013-2016; Throughput.html, "Throughput Utility Program", file example-data.txt,
// sequence P07,B05,G03,C03), a serial 1D task with touch input: A = 312.4, W = 130.2 (px), 20
// trials back and forth between x = 540.2 and x = 227.8 at y = 592. The table there gives the
// selection points to 0.1 px and the times to 1 ms; its printed results (from the unrounded file):
// Mean(x') = 6.86, SD(x') = 25.66, Misses = 1, Ae = 327.1, We = 106.1, IDe = 2.03, MT = 252.3 ms,
// Throughput = 8.04 bit/s (the -s summary: Ae 327.058351, We 106.062885, IDe 2.029851, MT
// 252.340000, 8.044111). Serial: each trial after the first begins at the previous selection,
// which is what `began` says. The tolerances are what rounding the table can move: 0.05 px on a
// coordinate, 0.5 ms on a time.
TEST(FittsTest, MacKenzieThroughputExample) {
  struct Row {
    double x, y, mt_ms;
  };
  const Row rows[] = {{218.5, 534.3, 263}, {529.5, 496.3, 268}, {195.0, 608.0, 248}, {533.5, 547.0, 234},
                      {209.8, 651.0, 251}, {607.0, 554.0, 253}, {231.3, 650.8, 283}, {540.8, 568.3, 215},
                      {231.9, 642.5, 301}, {560.5, 567.0, 267}, {207.5, 653.8, 259}, {524.5, 604.8, 259},
                      {239.1, 704.3, 248}, {515.0, 610.9, 243}, {180.0, 675.5, 242}, {501.0, 606.5, 253},
                      {215.5, 666.0, 244}, {572.0, 621.5, 256}, {215.4, 690.5, 252}, {521.5, 641.8, 210}};
  const double width = 130.2;
  std::vector<PointingTrial> trials;
  for (int i = 0; i < 20; ++i) {
    PointingTrial t;
    t.distance = 312.4;
    t.width = width;
    t.start = {i % 2 == 0 ? 540.2 : 227.8, 592.0, 0.0};
    t.target = {i % 2 == 0 ? 227.8 : 540.2, 592.0, 0.0};
    t.end = {rows[i].x, rows[i].y, 0.0};
    if (i > 0) t.began = trials.back().end;
    t.movement_time_s = rows[i].mt_ms / 1000.0;
    t.hit = std::abs(project_on_axis(t).dx) <= width / 2.0;  // 1D: a miss is |dx| > W / 2
    trials.push_back(t);
  }
  const FittsCell c = fitts_cell(trials);
  ASSERT_TRUE(c.computable()) << to_string(c.status);
  EXPECT_EQ(c.misses, 1);
  EXPECT_NEAR(c.error_percent, 5.0, 1e-12);
  EXPECT_NEAR(c.id_bits, 1.77, 0.005);
  EXPECT_NEAR(c.mean_dx, 6.86, 0.05);
  EXPECT_NEAR(c.sd_x, 25.66, 0.05);
  EXPECT_NEAR(c.effective_distance, 327.058351, 0.1);
  EXPECT_NEAR(c.effective_width, 106.062885, 0.2);
  EXPECT_NEAR(c.effective_id_bits, 2.029851, 0.003);
  EXPECT_NEAR(c.mean_mt_s, 0.25234, 0.0005);
  EXPECT_NEAR(c.throughput_bps, 8.044111, 0.02);
  std::printf("MacKenzie's example: Ae %.3f (327.058) We %.3f (106.063) IDe %.4f (2.0299) MT %.2f ms (252.34) "
              "TP %.4f (8.0441)\n",
              c.effective_distance, c.effective_width, c.effective_id_bits, 1000.0 * c.mean_mt_s, c.throughput_bps);
}

// Least squares against R's lm() and confint() (R 4.2.2) on six points x = 1..6,
// y = 0.52, 0.61, 0.83, 0.90, 1.12, 1.19. By hand: mean x 3.5, Sxx 17.5, mean y 5.17 / 6,
// Sxy = sum (x - 3.5) y = 2.475, so b = 2.475 / 17.5 = 0.141428571 and
// a = 5.17 / 6 - 3.5 b = 0.366666667. R: residual SD 0.0419750492781696, r^2 0.980263377229538,
// SE(a) 0.0390766442646261, SE(b) 0.0100339559550979, 95 % intervals a [0.25817250897059,
// 0.475160824362743], b [0.11356984353127, 0.169287299325873].
TEST(FittsTest, RegressionMatchesR) {
  const std::vector<double> x{1, 2, 3, 4, 5, 6}, y{0.52, 0.61, 0.83, 0.90, 1.12, 1.19};
  const LinearFit f = fit_line(x, y);
  ASSERT_TRUE(f.computable);
  EXPECT_EQ(f.points, 6);
  EXPECT_NEAR(f.slope, 0.141428571428571, 1e-12);
  EXPECT_NEAR(f.intercept, 0.366666666666667, 1e-12);
  EXPECT_NEAR(f.residual_sd, 0.0419750492781696, 1e-12);
  EXPECT_NEAR(f.r_squared, 0.980263377229538, 1e-12);
  EXPECT_NEAR(f.intercept_se, 0.0390766442646261, 1e-12);
  EXPECT_NEAR(f.slope_se, 0.0100339559550979, 1e-12);
  EXPECT_NEAR(f.intercept_ci.low, 0.25817250897059, 1e-10);
  EXPECT_NEAR(f.intercept_ci.high, 0.475160824362743, 1e-10);
  EXPECT_NEAR(f.slope_ci.low, 0.11356984353127, 1e-10);
  EXPECT_NEAR(f.slope_ci.high, 0.169287299325873, 1e-10);
}

// Throughput across participants against R's t.test(c(4.1, 4.6, 3.9, 5.2, 4.4)): mean 4.44,
// SD 0.502991053598372, 95 % interval [3.81545411732832, 5.06454588267168]. A participant
// without a throughput (NaN) is left out and counted.
TEST(FittsTest, MeanIntervalMatchesR) {
  const std::vector<double> tp{4.1, 4.6, std::nan(""), 3.9, 5.2, 4.4};
  const MeanInterval m = mean_interval(tp);
  ASSERT_TRUE(m.computable);
  EXPECT_EQ(m.n, 5);
  EXPECT_EQ(m.left_out, 1);
  EXPECT_NEAR(m.mean, 4.44, 1e-12);
  EXPECT_NEAR(m.sd, 0.502991053598372, 1e-12);
  EXPECT_NEAR(m.ci.low, 3.81545411732832, 1e-10);
  EXPECT_NEAR(m.ci.high, 5.06454588267168, 1e-10);
  const std::vector<double> one{4.1};
  const MeanInterval m1 = mean_interval(one);
  EXPECT_FALSE(m1.computable);
  EXPECT_EQ(m1.mean, 4.1);
  EXPECT_TRUE(std::isnan(m1.ci.low) && std::isnan(m1.ci.high));
}

PointingTrial trial_at(double d, double w, double end_x, double mt_s) {
  PointingTrial t;
  t.distance = d;
  t.width = w;
  t.target = {d, 0.0, 0.0};
  t.end = {end_x, 0.0, 0.0};
  t.movement_time_s = mt_s;
  t.hit = std::abs(end_x - d) <= w / 2.0;
  return t;
}

void expect_missing(const FittsCell& c, CellStatus why) {
  EXPECT_EQ(c.status, why) << to_string(c.status);
  EXPECT_FALSE(c.computable());
  // IDe needs no time, so a cell without one keeps it; nothing else missing has one.
  EXPECT_EQ(std::isnan(c.effective_id_bits), why != CellStatus::kNoTime);
  EXPECT_TRUE(std::isnan(c.throughput_bps));
  EXPECT_NE(to_string(c.status).find("not computable"), std::string_view::npos);
}

// Cells whose We, IDe or TP have no value are reported so, with NaN (never inf), and are left
// out of the participant's throughput and the IDe regression; the nominal regression keeps them.
TEST(FittsTest, DegenerateCellsAreNotComputable) {
  const std::vector<PointingTrial> one{trial_at(100, 20, 101, 0.6)};
  const FittsCell c1 = fitts_cell(one);
  expect_missing(c1, CellStatus::kTooFewTrials);
  EXPECT_EQ(c1.trials, 1);
  EXPECT_NEAR(c1.mean_mt_s, 0.6, 1e-15);  // what can be said is still said
  EXPECT_NEAR(c1.effective_distance, 101.0, 1e-12);
  EXPECT_TRUE(std::isnan(c1.effective_width));

  expect_missing(fitts_cell(std::vector<PointingTrial>{}), CellStatus::kTooFewTrials);

  const std::vector<PointingTrial> same{trial_at(100, 20, 102, 0.6), trial_at(100, 20, 102, 0.7),
                                        trial_at(100, 20, 102, 0.5)};
  const FittsCell c2 = fitts_cell(same);
  expect_missing(c2, CellStatus::kNoSpread);
  EXPECT_EQ(c2.sd_x, 0.0);
  EXPECT_TRUE(std::isnan(c2.effective_width));

  std::vector<PointingTrial> no_axis{trial_at(100, 20, 99, 0.6), trial_at(100, 20, 103, 0.6)};
  no_axis[1].target = no_axis[1].start;
  expect_missing(fitts_cell(no_axis), CellStatus::kNoAxis);

  const std::vector<PointingTrial> backwards{trial_at(100, 20, -5, 0.6), trial_at(100, 20, -9, 0.6)};
  expect_missing(fitts_cell(backwards), CellStatus::kNoAmplitude);

  const std::vector<PointingTrial> no_time{trial_at(100, 20, 95, 0.0), trial_at(100, 20, 104, 0.0)};
  expect_missing(fitts_cell(no_time), CellStatus::kNoTime);

  // A participant with nothing computable: no throughput, no IDe regression; only two cells with
  // a time, so no nominal regression either (it needs three points).
  std::vector<PointingTrial> p_trials = one;
  p_trials.insert(p_trials.end(), {trial_at(200, 20, 203, 0.8), trial_at(200, 20, 203, 0.9)});
  const FittsParticipant p = fitts_participant(p_trials);
  ASSERT_EQ(p.cells.size(), 2u);
  EXPECT_EQ(p.cells_used, 0);
  EXPECT_TRUE(std::isnan(p.throughput_bps));
  EXPECT_FALSE(p.on_id.computable);
  EXPECT_FALSE(p.on_effective_id.computable);
  EXPECT_TRUE(std::isnan(p.on_id.slope));
  // Every x equal: no slope.
  const std::vector<double> x{2, 2, 2}, y{1, 2, 3};
  EXPECT_FALSE(fit_line(x, y).computable);
  // Across participants, the one without a throughput is left out and counted.
  const std::vector<FittsParticipant> ps{p};
  const MeanInterval m = throughput_across(ps);
  EXPECT_FALSE(m.computable);
  EXPECT_EQ(m.n, 0);
  EXPECT_EQ(m.left_out, 1);
}

// The simulated pointer: the same seed gives the same trials; over many trials its end points
// along the axis have SD W / 4.133 (We = W), the misses come at P(|z| > 2.0665) = 3.88 %, the
// sideways scatter is there, and both noise shapes keep the mean and SD of MT.
TEST(PointingSimTest, DrawsWhatItIsAskedFor) {
  PointerParams params{0.2, 0.15, 0.08, false, 1.0, true};
  SimulatedPointer a(params, 7), b(params, 7);
  for (int i = 0; i < 10; ++i) {
    const PointingTrial ta = a.point(160, 20), tb = b.point(160, 20);
    EXPECT_EQ(ta.end.x, tb.end.x);
    EXPECT_EQ(ta.end.y, tb.end.y);
    EXPECT_EQ(ta.movement_time_s, tb.movement_time_s);
  }
  for (bool lognormal : {false, true}) {
    params.lognormal_mt = lognormal;
    SimulatedPointer p(params, 11);
    constexpr int kN = 40000;
    std::vector<PointingTrial> trials;
    for (int i = 0; i < kN; ++i) trials.push_back(p.point(160, 20));
    const FittsCell c = fitts_cell(trials);
    double sum_y2 = 0.0;
    for (const PointingTrial& t : trials) sum_y2 += t.end.y * t.end.y;
    // Standard errors at N = 40000: SD of an SD ~ sigma / sqrt(2N) = 0.35 %; of the miss rate
    // sqrt(0.0388 x 0.9612 / N) = 0.097 points; of the mean MT 0.08 / 200 = 0.0004 s.
    const double mean_mt = 0.2 + 0.15 * std::log2(9.0);
    EXPECT_NEAR(c.sd_x, 20.0 / 4.133, 0.015 * 20.0 / 4.133) << lognormal;
    EXPECT_NEAR(c.effective_width, 20.0, 0.3) << lognormal;
    EXPECT_NEAR(std::sqrt(sum_y2 / kN), 20.0 / 4.133, 0.015 * 20.0 / 4.133) << lognormal;
    EXPECT_NEAR(c.error_percent, 3.88, 0.4) << lognormal;
    EXPECT_NEAR(c.mean_mt_s, mean_mt, 0.0015) << lognormal;
    EXPECT_NEAR(c.effective_distance, 160.0, 0.1) << lognormal;
    double ss = 0.0;
    for (const PointingTrial& t : trials) ss += (t.movement_time_s - c.mean_mt_s) * (t.movement_time_s - c.mean_mt_s);
    EXPECT_NEAR(std::sqrt(ss / (kN - 1)), 0.08, 0.08 * 0.03) << lognormal;
  }
}

// Known Fitts laws recovered: 50 simulated participants per law, each through 3 distances x 3
// widths (80, 160, 320 mm x 10, 20, 40 mm: ID 1.58 to 5.04 bits) at 20 trials a cell, MT noise SD
// 0.08 s, end points aimed so that We = W. The regression on the nominal ID meets ordinary least
// squares' assumptions exactly (Gaussian noise of one SD, averaged over 20 trials per cell), so
// its 95 % intervals should hold the true a and b in 95 % of runs; the test asks for at least
// 45 of 50 (90 %; P(fewer | 95 %) = 3.8 %). The expected throughput: with We = W, IDe = ID and
// each cell's TP is ID / (a + b ID); its mean over the nine cells is what the mean of means
// estimates.
TEST(PointingSimTest, KnownFittsLawRecovered) {
  struct Law {
    double a, b;
  };
  const std::vector<double> distances{80, 160, 320}, widths{10, 20, 40};
  constexpr int kRuns = 50, kTrials = 20;
  const Law laws[] = {{0.2, 0.15}, {0.1, 0.25}, {0.3, 0.1}};
  for (int l = 0; l < 3; ++l) {
    const Law law = laws[l];
    double expected_tp = 0.0;
    for (double d : distances)
      for (double w : widths) {
        const double id = std::log2(d / w + 1.0);
        expected_tp += id / (law.a + law.b * id) / 9.0;
      }
    int a_in = 0, b_in = 0, ae_in = 0, be_in = 0;
    double sum_a = 0.0, sum_b = 0.0, sum_ae = 0.0, sum_be = 0.0, sum_r2 = 0.0, sum_err = 0.0;
    double worst_tp = 0.0;
    std::vector<FittsParticipant> participants;
    for (int run = 0; run < kRuns; ++run) {
      // Seeds of their own per law: with shared seeds the three laws would draw the same noise,
      // and whether an interval holds the truth depends on the noise alone.
      SimulatedPointer pointer({law.a, law.b, 0.08, false, 1.0, true}, 1000 * (l + 1) + run);
      const std::vector<PointingTrial> trials = simulate_design(pointer, distances, widths, kTrials);
      FittsParticipant p = fitts_participant(trials);
      ASSERT_EQ(p.cells_used, 9);
      ASSERT_TRUE(p.on_id.computable && p.on_effective_id.computable);
      a_in += p.on_id.intercept_ci.contains(law.a);
      b_in += p.on_id.slope_ci.contains(law.b);
      ae_in += p.on_effective_id.intercept_ci.contains(law.a);
      be_in += p.on_effective_id.slope_ci.contains(law.b);
      sum_a += p.on_id.intercept, sum_b += p.on_id.slope, sum_r2 += p.on_id.r_squared;
      sum_ae += p.on_effective_id.intercept, sum_be += p.on_effective_id.slope;
      for (const FittsCell& c : p.cells) sum_err += c.error_percent / 9.0;
      worst_tp = std::max(worst_tp, std::abs(p.throughput_bps / expected_tp - 1.0));
      participants.push_back(std::move(p));
    }
    const MeanInterval tp = throughput_across(participants);
    std::printf("a %.2f b %.2f: on ID a in CI %d/%d, b in CI %d/%d, mean a %.4f b %.4f r2 %.3f; on IDe a in CI "
                "%d/%d, b %d/%d, mean a %.4f b %.4f; TP %.4f [%.4f, %.4f] expected %.4f (%+.2f %%), worst "
                "participant %.1f %%; errors %.2f %%\n",
                law.a, law.b, a_in, kRuns, b_in, kRuns, sum_a / kRuns, sum_b / kRuns, sum_r2 / kRuns, ae_in, kRuns,
                be_in, kRuns, sum_ae / kRuns, sum_be / kRuns, tp.mean, tp.ci.low, tp.ci.high, expected_tp,
                100.0 * (tp.mean / expected_tp - 1.0), 100.0 * worst_tp, sum_err / kRuns);
    EXPECT_GE(a_in, 45) << law.a << " " << law.b;
    EXPECT_GE(b_in, 45) << law.a << " " << law.b;
    // The mean fit over 50 runs: SE(b) per run is 0.08 / sqrt(20) / sqrt(Sxx) with Sxx = 9.127
    // (the nine IDs about their mean 3.218), 0.0059 s/bit, so 0.0008 over 50 runs; SE(a) is
    // 0.08 / sqrt(20) x sqrt(1/9 + 3.218^2 / 9.127) = 0.020 s per run, 0.0028 over 50. The
    // tolerances are about 4.5 of those.
    EXPECT_NEAR(sum_b / kRuns, law.b, 0.004);
    EXPECT_NEAR(sum_a / kRuns, law.a, 0.012);
    // Throughput: the mean of 50 participants is expected 1.2 % above ID / (a + b ID) averaged
    // over the cells. The bias is the estimator's, not the code's: log SDx from 20 points
    // averages about 1 / (2 x 19) = 2.6 % below log sigma, so We runs low and IDe high by about
    // 0.026 / ln 2 x (D/W) / (D/W + 1) = 0.034 bits of some 3 (4000 simulated participants per
    // law: +1.19 to +1.20 %). A participant's TP scatters by about 2.9 %, so the mean of 50 by
    // 0.41 %; the test allows 3 of those about +1.2 %. The same bias is why the 95 % interval
    // (half width about 0.8 %) is not asked to hold the unbiased value.
    ASSERT_TRUE(tp.computable);
    EXPECT_EQ(tp.n, kRuns);
    EXPECT_NEAR(tp.mean / expected_tp, 1.012, 0.013);
    EXPECT_NEAR(sum_err / kRuns, 3.88, 1.0);
  }
}

}  // namespace
}  // namespace ps::study
