#include "study/psychometric.h"

#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>

namespace ps::study {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Phi^-1 by Newton's method on erfc, started from the logistic that best matches Phi: it is
// needed for thresholds only, never inside a likelihood, so a few Newton steps are cheap enough.
double normal_quantile(double f) {
  double z = std::log(f / (1.0 - f)) / 1.702;  // the logistic that best matches Phi
  for (int i = 0; i < 60; ++i) {
    const double err = 0.5 * std::erfc(-z / std::numbers::sqrt2) - f;
    const double dens = std::exp(-0.5 * z * z) / std::sqrt(2.0 * std::numbers::pi);
    const double next = z - err / dens;
    if (std::abs(next - z) < 1e-15 * (1.0 + std::abs(z))) return next;
    z = next;
  }
  return z;
}

}  // namespace

double shape_cdf(Shape shape, double x, double threshold, double slope) {
  switch (shape) {
    case Shape::kLogistic: return 1.0 / (1.0 + std::exp(-slope * (x - threshold)));
    case Shape::kWeibull: return x <= 0.0 ? 0.0 : -std::expm1(-std::pow(x / threshold, slope));
    case Shape::kCumulativeNormal: return 0.5 * std::erfc(-slope * (x - threshold) / std::numbers::sqrt2);
  }
  return kNaN;
}

double shape_inverse(Shape shape, double f, double threshold, double slope) {
  if (!(f > 0.0 && f < 1.0)) return kNaN;
  switch (shape) {
    case Shape::kLogistic: return threshold + std::log(f / (1.0 - f)) / slope;
    case Shape::kWeibull: return threshold * std::pow(-std::log1p(-f), 1.0 / slope);
    case Shape::kCumulativeNormal: return threshold + normal_quantile(f) / slope;
  }
  return kNaN;
}

double shape_density(Shape shape, double x, double threshold, double slope) {
  switch (shape) {
    case Shape::kLogistic: {
      const double f = shape_cdf(shape, x, threshold, slope);
      return slope * f * (1.0 - f);
    }
    case Shape::kWeibull: {
      if (x <= 0.0) return 0.0;
      const double u = std::pow(x / threshold, slope);
      return slope / x * u * std::exp(-u);
    }
    case Shape::kCumulativeNormal: {
      const double z = slope * (x - threshold);
      return slope * std::exp(-0.5 * z * z) / std::sqrt(2.0 * std::numbers::pi);
    }
  }
  return kNaN;
}

double psi(Shape shape, const PsychometricParams& p, double x) {
  return p.guess + (1.0 - p.guess - p.lapse) * shape_cdf(shape, x, p.threshold, p.slope);
}

double threshold_at(Shape shape, const PsychometricParams& p, double p_correct) {
  const double span = 1.0 - p.guess - p.lapse;
  assert(span > 0.0 && "threshold_at: guess + lapse must stay below 1");
  return shape_inverse(shape, (p_correct - p.guess) / span, p.threshold, p.slope);
}

double slope_at(Shape shape, const PsychometricParams& p, double x) {
  return (1.0 - p.guess - p.lapse) * shape_density(shape, x, p.threshold, p.slope);
}

double weber_fraction(double threshold, double reference) { return threshold / reference; }

std::string_view shape_name(Shape shape) {
  switch (shape) {
    case Shape::kLogistic: return "logistic";
    case Shape::kWeibull: return "weibull";
    case Shape::kCumulativeNormal: return "normal";
  }
  return "?";
}

}  // namespace ps::study
