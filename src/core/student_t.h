// Student's t distribution: its CDF and quantile for df >= 1 degrees of freedom, through the
// regularized incomplete beta function (Press et al., Numerical Recipes, 3rd ed., §6.4), the
// quantile inverted by bisection to double precision. One t for every interval of the project:
// the maze's group summaries (maze/maze_summary.h) and the study's regressions and means
// (study/fitts.h). Checked against R's qt() and pt() in tests/study/fitts_test.cpp.
#pragma once

#include <cmath>
#include <limits>

namespace ps {

namespace student_t_detail {

// The continued fraction of the regularized incomplete beta function, evaluated by the modified
// Lentz method (Press et al., Numerical Recipes, 3rd ed., §6.4); converges fast for
// x < (a + 1) / (a + b + 2), which the caller arranges by symmetry.
inline double beta_continued_fraction(double a, double b, double x) {
  constexpr double kTiny = 1e-300;
  const double qab = a + b, qap = a + 1.0, qam = a - 1.0;
  double c = 1.0, d = 1.0 - qab * x / qap;
  if (std::abs(d) < kTiny) d = kTiny;
  d = 1.0 / d;
  double h = d;
  for (int m = 1; m <= 10000; ++m) {
    const double m2 = 2.0 * m;
    double aa = m * (b - m) * x / ((qam + m2) * (a + m2));
    d = 1.0 + aa * d;
    if (std::abs(d) < kTiny) d = kTiny;
    c = 1.0 + aa / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    h *= d * c;
    aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2));
    d = 1.0 + aa * d;
    if (std::abs(d) < kTiny) d = kTiny;
    c = 1.0 + aa / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double del = d * c;
    h *= del;
    if (std::abs(del - 1.0) < 1e-16) break;
  }
  return h;
}

// I_x(a, b).
inline double incomplete_beta(double a, double b, double x) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  const double log_front =
      std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x);
  if (x < (a + 1.0) / (a + b + 2.0)) return std::exp(log_front) * beta_continued_fraction(a, b, x) / a;
  return 1.0 - std::exp(log_front) * beta_continued_fraction(b, a, 1.0 - x) / b;
}

// P(T > t) for t >= 0: half of I_{df / (df + t^2)}(df / 2, 1 / 2). Computed as the tail, not as
// 1 - CDF, so that quantiles near 1 keep their digits.
inline double t_upper_tail(double t, double df) { return 0.5 * incomplete_beta(0.5 * df, 0.5, df / (df + t * t)); }

}  // namespace student_t_detail

// NaN for df < 1 or a NaN t.
inline double student_t_cdf(double t, double df) {
  if (!(df >= 1.0) || std::isnan(t)) return std::numeric_limits<double>::quiet_NaN();
  const double tail = student_t_detail::t_upper_tail(std::abs(t), df);
  return t >= 0.0 ? 1.0 - tail : tail;
}

// NaN for df < 1 or p outside (0, 1).
inline double student_t_quantile(double p, double df) {
  if (!(df >= 1.0) || !(p > 0.0 && p < 1.0)) return std::numeric_limits<double>::quiet_NaN();
  if (p == 0.5) return 0.0;
  if (p < 0.5) return -student_t_quantile(1.0 - p, df);
  // Find t > 0 with P(T > t) = 1 - p: the tail falls monotonically in t, so bracket and bisect.
  const double q = 1.0 - p;
  double lo = 0.0, hi = 1.0;
  while (student_t_detail::t_upper_tail(hi, df) > q && hi < 1e300) lo = hi, hi *= 2.0;
  for (int i = 0; i < 2000 && hi - lo > 1e-15 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (student_t_detail::t_upper_tail(mid, df) > q ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace ps
