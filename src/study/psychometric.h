// The psychometric function of a forced-choice task (docs/study.md, "The psychometric function";
// Wichmann & Hill 2001): the probability of a correct answer at stimulus level x,
//
//   psi(x) = gamma + (1 - gamma - lambda) F(x; alpha, beta)
//
// with gamma the guess rate (1/2 in 2AFC), lambda the lapse rate (answers wrong whatever the
// level), alpha the threshold and beta the slope parameter of the shape F:
//   logistic           F = 1 / (1 + exp(-beta (x - alpha)))     F(alpha) = 1/2
//   Weibull (x > 0)    F = 1 - exp(-(x / alpha)^beta)           F(alpha) = 1 - 1/e
//   cumulative normal  F = Phi(beta (x - alpha))                F(alpha) = 1/2
// Levels are in the stimulus's own units (mm, degrees, ...); alpha is in those units, beta in
// their inverse (logistic, normal) or without unit (Weibull).
#pragma once

#include <string_view>

namespace ps::study {

enum class Shape { kLogistic, kWeibull, kCumulativeNormal };

struct PsychometricParams {
  double threshold = 1.0;  // alpha, stimulus units
  double slope = 1.0;      // beta
  double guess = 0.5;      // gamma
  double lapse = 0.0;      // lambda
};

// F(x) of the shape, in [0, 1]; the Weibull is 0 for x <= 0.
double shape_cdf(Shape shape, double x, double threshold, double slope);
// The x with F(x) = f, f in (0, 1).
double shape_inverse(Shape shape, double f, double threshold, double slope);
// dF/dx.
double shape_density(Shape shape, double x, double threshold, double slope);

double psi(Shape shape, const PsychometricParams& p, double x);

// The level at which psi reaches `p_correct` (the criterion, e.g. 0.75 or 1/sqrt 2 in 2AFC):
// F^-1((p_correct - gamma) / (1 - gamma - lambda)). NaN when psi never reaches it (p_correct at
// or below gamma, or at or above 1 - lambda).
double threshold_at(Shape shape, const PsychometricParams& p, double p_correct);

// dpsi/dx at x: the slope of the curve a reader sees (per stimulus unit).
double slope_at(Shape shape, const PsychometricParams& p, double x);

// The Weber fraction of a threshold measured at a reference level: threshold / reference.
double weber_fraction(double threshold, double reference);

std::string_view shape_name(Shape shape);  // "logistic", "weibull", "normal"

}  // namespace ps::study
