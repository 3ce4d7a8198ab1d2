// The psychometric function's shapes, thresholds and slopes against values worked by hand or
// taken from tables (study/psychometric.h).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "study/psychometric.h"

namespace ps::study {
namespace {

// Each shape at its defining points: logistic and normal 1/2 at alpha, the Weibull 1 - 1/e;
// logistic 3/4 at alpha + ln 3 / beta (1 / (1 + 1/3)); normal Phi(1) = 0.8413447461 one 1/beta
// above alpha (the normal table's value, to its 10 digits).
TEST(PsychometricTest, ShapesPassThroughTheirDefiningPoints) {
  EXPECT_DOUBLE_EQ(shape_cdf(Shape::kLogistic, 2.0, 2.0, 7.0), 0.5);
  EXPECT_DOUBLE_EQ(shape_cdf(Shape::kCumulativeNormal, 2.0, 2.0, 7.0), 0.5);
  EXPECT_DOUBLE_EQ(shape_cdf(Shape::kWeibull, 2.0, 2.0, 7.0), 1.0 - std::exp(-1.0));
  EXPECT_NEAR(shape_cdf(Shape::kLogistic, 2.0 + std::log(3.0) / 7.0, 2.0, 7.0), 0.75, 1e-15);
  EXPECT_NEAR(shape_cdf(Shape::kCumulativeNormal, 2.0 + 1.0 / 7.0, 2.0, 7.0), 0.8413447461, 1e-10);
  EXPECT_EQ(shape_cdf(Shape::kWeibull, 0.0, 2.0, 7.0), 0.0);
  EXPECT_EQ(shape_cdf(Shape::kWeibull, -1.0, 2.0, 7.0), 0.0);
}

// The normal quantile against its table value Phi^-1(0.975) = 1.959963985; the other shapes'
// inverses by their closed forms worked here (logistic: ln(f / (1 - f)); Weibull: (-ln(1 - f))^(1/beta)).
TEST(PsychometricTest, InversesMatchTableAndClosedForms) {
  EXPECT_NEAR(shape_inverse(Shape::kCumulativeNormal, 0.975, 0.0, 1.0), 1.959963985, 1e-9);
  EXPECT_NEAR(shape_inverse(Shape::kCumulativeNormal, 0.5, 3.0, 2.0), 3.0, 1e-15);
  EXPECT_NEAR(shape_inverse(Shape::kLogistic, 0.9, 1.0, 2.0), 1.0 + std::log(9.0) / 2.0, 1e-15);
  EXPECT_NEAR(shape_inverse(Shape::kWeibull, 0.5, 0.1, 3.0), 0.1 * std::cbrt(std::log(2.0)), 1e-16);
  EXPECT_TRUE(std::isnan(shape_inverse(Shape::kLogistic, 1.0, 0.0, 1.0)));
}

// 2AFC (gamma 1/2): with no lapse the 75 % point of a logistic and the 1/2 + (1 - 1/e)/2 point of
// a Weibull are alpha exactly. With lambda = 0.02 the logistic's 75 % point is where
// F = 0.25 / 0.48 = 0.5208333: alpha + ln(0.5208333 / 0.4791667) / beta = 0.1 + 0.0833816 / 20
// = 0.1041691 (worked by hand for beta = 20).
TEST(PsychometricTest, ThresholdAtCriterionByHand) {
  const PsychometricParams p{.threshold = 0.1, .slope = 20.0, .guess = 0.5, .lapse = 0.0};
  EXPECT_NEAR(threshold_at(Shape::kLogistic, p, 0.75), 0.1, 1e-15);
  EXPECT_NEAR(threshold_at(Shape::kWeibull, {0.1, 3.0, 0.5, 0.0}, 0.5 + 0.5 * (1.0 - std::exp(-1.0))), 0.1, 1e-15);
  PsychometricParams lapsing = p;
  lapsing.lapse = 0.02;
  EXPECT_NEAR(threshold_at(Shape::kLogistic, lapsing, 0.75), 0.1041691, 1e-7);
  EXPECT_NEAR(psi(Shape::kLogistic, lapsing, 1e9), 0.98, 1e-12);  // the lapse caps the curve
  EXPECT_TRUE(std::isnan(threshold_at(Shape::kLogistic, lapsing, 0.99)));  // never reached
  EXPECT_TRUE(std::isnan(threshold_at(Shape::kLogistic, lapsing, 0.5)));   // the guess rate
}

// The closed-form slope against a central difference of psi itself (step 1e-6 of a level near
// 0.1: truncation ~ h^2 psi''' ~ 1e-8 relative, rounding ~ 1e-16 / 1e-6 = 1e-10).
TEST(PsychometricTest, SlopeIsTheDerivative) {
  for (Shape shape : {Shape::kLogistic, Shape::kWeibull, Shape::kCumulativeNormal}) {
    const PsychometricParams p{.threshold = 0.1, .slope = shape == Shape::kWeibull ? 3.0 : 30.0, .guess = 0.5, .lapse = 0.03};
    for (double x : {0.05, 0.1, 0.13, 0.2}) {
      const double h = 1e-6;
      const double numeric = (psi(shape, p, x + h) - psi(shape, p, x - h)) / (2.0 * h);
      EXPECT_NEAR(slope_at(shape, p, x), numeric, 1e-6 * std::abs(numeric) + 1e-9) << shape_name(shape) << " at " << x;
    }
  }
  // The logistic's at alpha by hand: (1 - gamma - lambda) beta / 4.
  EXPECT_DOUBLE_EQ(slope_at(Shape::kLogistic, {0.1, 30.0, 0.5, 0.02}, 0.1), 0.48 * 30.0 / 4.0);
}

TEST(PsychometricTest, WeberFractionIsThresholdOverReference) {
  EXPECT_DOUBLE_EQ(weber_fraction(0.1, 2.0), 0.05);
}

}  // namespace
}  // namespace ps::study
