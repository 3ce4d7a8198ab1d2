#include "study/nelder_mead.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numeric>

namespace ps::study {
namespace {

struct Simplex {
  std::vector<std::vector<double>> x;  // n + 1 vertices
  std::vector<double> f;

  void sort() {
    std::vector<int> order(f.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return f[a] < f[b]; });
    std::vector<std::vector<double>> xs;
    std::vector<double> fs;
    for (int i : order) {
      xs.push_back(x[i]);
      fs.push_back(f[i]);
    }
    x = std::move(xs);
    f = std::move(fs);
  }
  bool small(const NelderMeadParams& p) const {
    if (!(std::abs(f.back() - f.front()) <= p.f_tolerance)) return false;
    for (std::size_t v = 1; v < x.size(); ++v)
      for (std::size_t i = 0; i < x[0].size(); ++i)
        if (std::abs(x[v][i] - x[0][i]) > p.x_tolerance) return false;
    return true;
  }
};

// centroid + t (centroid - worst): t = 1 reflects, 2 expands, 1/2 and -1/2 contract.
std::vector<double> along(const std::vector<double>& centroid, const std::vector<double>& worst, double t) {
  std::vector<double> out(centroid.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = centroid[i] + t * (centroid[i] - worst[i]);
  return out;
}

std::vector<double> centroid_of_best(const Simplex& s) {
  const std::size_t n = s.x[0].size();
  std::vector<double> c(n, 0.0);
  for (std::size_t v = 0; v < n; ++v)
    for (std::size_t i = 0; i < n; ++i) c[i] += s.x[v][i] / static_cast<double>(n);
  return c;
}

// One move of the worst vertex: reflect through the others' centroid, expand if that is the new
// best, contract if it is no better than the second worst, shrink all towards the best if even
// the contraction fails.
template <class Eval>
void step(Simplex& s, const Eval& eval) {
  const std::size_t n = s.x.size() - 1;
  const std::vector<double> c = centroid_of_best(s);
  const auto reflected = along(c, s.x[n], 1.0);
  const double fr = eval(reflected);
  if (fr < s.f[0]) {
    const auto expanded = along(c, s.x[n], 2.0);
    const double fe = eval(expanded);
    s.x[n] = fe < fr ? expanded : reflected;
    s.f[n] = std::min(fe, fr);
  } else if (fr < s.f[n - 1]) {
    s.x[n] = reflected;
    s.f[n] = fr;
  } else {
    const auto contracted = along(c, s.x[n], fr < s.f[n] ? 0.5 : -0.5);  // outside or inside
    const double fc = eval(contracted);
    if (fc < std::min(fr, s.f[n])) {
      s.x[n] = contracted;
      s.f[n] = fc;
    } else {
      for (std::size_t v = 1; v <= n; ++v) {
        for (std::size_t i = 0; i < n; ++i) s.x[v][i] = s.x[0][i] + 0.5 * (s.x[v][i] - s.x[0][i]);
        s.f[v] = eval(s.x[v]);
      }
    }
  }
  s.sort();
}

}  // namespace

NelderMeadResult nelder_mead(const Objective& f, std::vector<double> start, const NelderMeadParams& params) {
  const std::size_t n = start.size();
  assert(params.step.size() == n && "nelder_mead: one step per parameter");
  NelderMeadResult r;
  auto eval = [&](const std::vector<double>& x) {
    ++r.evaluations;
    const double v = f(x);
    return std::isnan(v) ? INFINITY : v;
  };
  Simplex s;
  s.x.push_back(start);
  for (std::size_t i = 0; i < n; ++i) {
    s.x.push_back(start);
    s.x.back()[i] += params.step[i];
  }
  for (const auto& x : s.x) s.f.push_back(eval(x));
  s.sort();
  while (r.evaluations < params.max_evaluations && !(r.converged = s.small(params))) step(s, eval);
  r.x = s.x[0];
  r.f = s.f[0];
  return r;
}

}  // namespace ps::study
