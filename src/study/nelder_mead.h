// A small Nelder-Mead simplex minimiser (Nelder & Mead 1965, the coefficients of Lagarias et al.
// 1998: reflection 1, expansion 2, contraction 1/2, shrink 1/2) for the 2-3 parameters of a
// psychometric fit. Bounds are the objective's business: it returns +infinity outside them, and
// a simplex that starts inside never accepts such a point. Why not a library: docs/study.md,
// "Decisions".
#pragma once

#include <functional>
#include <vector>

namespace ps::study {

struct NelderMeadParams {
  std::vector<double> step;     // the first simplex: start + step[i] along axis i
  double f_tolerance = 1e-10;   // stop when the simplex's values differ by less than this ...
  double x_tolerance = 1e-9;    // ... and its vertices by less than this along every axis
  int max_evaluations = 4000;
};

struct NelderMeadResult {
  std::vector<double> x;
  double f = 0.0;
  int evaluations = 0;
  bool converged = false;  // the tolerances were met before max_evaluations
};

using Objective = std::function<double(const std::vector<double>&)>;

NelderMeadResult nelder_mead(const Objective& f, std::vector<double> start, const NelderMeadParams& params);

}  // namespace ps::study
