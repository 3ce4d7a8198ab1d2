// The simplex minimiser (study/nelder_mead.h) on functions whose minimum is known in closed form.
#include <cmath>

#include <gtest/gtest.h>

#include "study/nelder_mead.h"

namespace ps::study {
namespace {

// Rosenbrock's valley, (1 - x)^2 + 100 (y - x^2)^2: minimum 0 at (1, 1), reached along a curved
// ridge, the classic hard case for a simplex. From (-1.2, 1) (the customary start); the
// tolerances stop it within about 1e-4 of the point (f is flat to 1e-8 there).
TEST(NelderMeadTest, FindsRosenbrocksMinimum) {
  const Objective f = [](const std::vector<double>& v) {
    return (1 - v[0]) * (1 - v[0]) + 100 * (v[1] - v[0] * v[0]) * (v[1] - v[0] * v[0]);
  };
  NelderMeadParams p;
  p.step = {0.5, 0.5};
  const NelderMeadResult r = nelder_mead(f, {-1.2, 1.0}, p);
  EXPECT_TRUE(r.converged);
  EXPECT_NEAR(r.x[0], 1.0, 1e-4);
  EXPECT_NEAR(r.x[1], 1.0, 1e-4);
  EXPECT_LT(r.f, 1e-8);
}

// A bound as +infinity: (x - 3)^2 on x <= 2 has its minimum on the bound, x = 2; NaN counts as
// +infinity too.
TEST(NelderMeadTest, StaysInsideBoundsGivenAsInfinity) {
  const Objective f = [](const std::vector<double>& v) -> double {
    if (v[0] > 2.0) return INFINITY;
    if (v[0] < -5.0) return NAN;
    return (v[0] - 3.0) * (v[0] - 3.0);
  };
  NelderMeadParams p;
  p.step = {0.5};
  const NelderMeadResult r = nelder_mead(f, {0.0}, p);
  EXPECT_LE(r.x[0], 2.0);
  EXPECT_NEAR(r.x[0], 2.0, 1e-8);
}

}  // namespace
}  // namespace ps::study
