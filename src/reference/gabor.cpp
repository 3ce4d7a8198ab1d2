#include "reference/gabor.h"

#include "reference/gabor_internal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace ps {

namespace {

// Variance of the sparse-convolution process for A == 1 (Lagae et al. 2009, eq. for random
// phase). The phases are independent and uniform, so cross terms vanish and the variance is
// the expected number of impulses per mm^2 times the mean squared kernel's integral: cos^2
// averages to 1/2, and the squared envelope exp(-2 r^2/W^2) cut at r^2 = W^2 T (T = -ln t)
// integrates to (pi W^2 / 2)(1 - t^2). With E[count] impulses per C x C cell,
//   sigma^2 = E[count] / C^2 * (1/2) * (pi / 2) E[W^2] (1 - t^2).
// E[count] is that of the count drawn (expected_cell_count), cap included.
double unit_sigma(const GaborParams& g, const GaborSetup& s) {
  const double a = g.lambda_min_mm, b = g.lambda_max_mm;
  const double e_lambda2 = (a * a + a * b + b * b) / 3.0;  // lambda ~ U[a, b]
  const double e_w2 = g.kernel_periods * g.kernel_periods * e_lambda2;
  const double kept = 1.0 - std::exp(-2.0 * s.trunc_factor);  // 1 - t^2
  const double var = expected_cell_count(g, s) * std::numbers::pi * e_w2 * kept / (4.0 * s.cell_mm * s.cell_mm);
  return var > 0.0 ? std::sqrt(var) : 1.0;
}

}  // namespace

GaborSetup make_gabor_setup(const GaborParams& g) {
  GaborSetup s;
  s.trunc_factor = -std::log(std::clamp(g.truncation, 1e-12, 0.999999));
  const double lambda_max = std::max(g.lambda_min_mm, g.lambda_max_mm);
  s.cell_mm = std::max(1e-6, g.kernel_periods * lambda_max * std::sqrt(s.trunc_factor));
  s.max_impulses = std::max(0, g.max_impulses_per_cell);
  if (g.strategy == GaborParams::Strategy::kStratified)
    s.stratified_count = std::clamp(g.stratified_impulses, 1, std::max(1, s.max_impulses));
  s.sigma_unit = unit_sigma(g, s);
  return s;
}

std::uint32_t fmix32(std::uint32_t h) {  // murmur3's finaliser; GLSL twin gabor_fmix32
  h = (h ^ (h >> 16)) * 0x85ebca6bu;
  h = (h ^ (h >> 13)) * 0xc2b2ae35u;
  return h ^ (h >> 16);
}

namespace {
// The cell's key hashed with the material seed (gabor.h, gabor_cell_seed): a bijection of the
// keys for each seed.
std::uint32_t cell_hash(std::uint32_t key, std::uint32_t seed) {
  return fmix32(fmix32(key) ^ fmix32(seed + kGaborSeedOffset));
}
}  // namespace

std::uint32_t gabor_cell_seed(int cx, int cy, std::uint32_t seed) {
  const std::uint32_t key = (static_cast<std::uint32_t>(cx) & 0xffffu) | (static_cast<std::uint32_t>(cy) << 16);
  const std::uint32_t h = cell_hash(key, seed);
  // The LCG must not start at 0. The one key hashing to 0 takes the state of the key half a
  // period away on both axes (hash is a bijection, so that state is not 0): the only repeat
  // in the period, out of reach of any window of 32768 cells a side.
  return h != 0u ? h : cell_hash(key ^ kGaborHalfPeriodKey, seed);
}

double expected_cell_count(const GaborParams& g, const GaborSetup& s) {
  const double cap = s.max_impulses;
  if (s.stratified_count > 0) return std::min<double>(s.stratified_count, cap);
  // count = floor(x + u), x = n / pi, u ~ U[0, 1): floor(x) + 1 with probability frac(x),
  // so E[count | x] = x, and for an integer cap E[min(count, cap) | x] = min(x, cap) (below
  // the cap both outcomes are <= cap; at or above it both are >= cap). Averaged over
  // x ~ U[x0, x1]:
  const double x0 = std::min(g.n_min, g.n_max) / std::numbers::pi, x1 = std::max(g.n_min, g.n_max) / std::numbers::pi;
  if (x1 <= cap) return 0.5 * (x0 + x1);
  if (x0 >= cap) return cap;
  return (0.5 * (cap * cap - x0 * x0) + cap * (x1 - cap)) / (x1 - x0);
}

float lcg_uniform(std::uint32_t& state) {
  state *= kLcgMultiplier;  // mod 2^32 by unsigned wrap-around
  return static_cast<float>(state) * (1.0f / 4294967296.0f);
}

namespace gabor_detail {

int cell_count(const GaborParams& g, const GaborSetup& s, std::uint32_t& r) {
  if (s.stratified_count > 0) return std::min(s.stratified_count, s.max_impulses);
  // Same float operations as the shader (mix = a + (b - a) * t) so counts match bit for bit.
  const float n_min = static_cast<float>(g.n_min), n_max = static_cast<float>(g.n_max);
  const float n = n_min + (n_max - n_min) * lcg_uniform(r);
  const float expected = n * static_cast<float>(1.0 / std::numbers::pi);
  const int count = static_cast<int>(std::floor(expected + lcg_uniform(r)));
  return std::clamp(count, 0, s.max_impulses);
}

// The k-th impulse of a cell, relative to the point (px, py) in the cell's frame: the draws in
// the shader's order and float operations. Naive: one stratum (the whole cell); stratified: a
// grid x grid jittered grid (stratum_grid). Impulse: gabor_internal.h.
int stratum_grid(const GaborSetup& s) {
  return s.stratified_count > 0 ? static_cast<int>(std::ceil(std::sqrt(static_cast<float>(s.stratified_count)))) : 1;
}
Impulse draw_impulse(const GaborParams& g, const GaborSetup& s, std::uint32_t& r, int k, int grid,
                     double px, double py) {
  const float inv_grid = 1.0f / static_cast<float>(grid);
  Impulse i;
  const float jx = (static_cast<float>(k % grid) + lcg_uniform(r)) * inv_grid;
  const float jy = (static_cast<float>((k / grid) % grid) + lcg_uniform(r)) * inv_grid;
  i.dx = px - jx * s.cell_mm;
  i.dy = py - jy * s.cell_mm;
  i.amp = std::lerp(g.a_min, g.a_max, static_cast<double>(lcg_uniform(r)));
  i.lambda = std::lerp(g.lambda_min_mm, g.lambda_max_mm, static_cast<double>(lcg_uniform(r)));
  i.theta = std::lerp(g.theta_min_rad, g.theta_max_rad, static_cast<double>(lcg_uniform(r)));
  i.psi = 2.0 * std::numbers::pi * lcg_uniform(r);
  i.w = g.kernel_periods * i.lambda;
  i.r2 = i.dx * i.dx + i.dy * i.dy;
  return i;
}

}  // namespace gabor_detail

namespace {

using namespace gabor_detail;

double cell_sum(const GaborParams& g, const GaborSetup& s, std::uint32_t seed, int cx, int cy,
                double px, double py, double* margin = nullptr, double trunc_factor = 0.0) {
  if (trunc_factor <= 0.0) trunc_factor = s.trunc_factor;
  double sum = 0.0;
  for_each_impulse(g, s, seed, cx, cy, px, py, [&](const Impulse& im) {
    const auto [dx, dy, amp, lambda, theta, psi, w, r2] = im;
    if (margin && w > 0.0)
      *margin = std::min(*margin, std::abs(std::sqrt(r2) - w * std::sqrt(s.trunc_factor)));
    if (w <= 0.0 || r2 >= w * w * trunc_factor) return;
    const double phase = 2.0 * std::numbers::pi * (dx * std::cos(theta) + dy * std::sin(theta)) / lambda;
    sum += amp * std::exp(-r2 / (w * w)) * std::cos(phase + psi);
  });
  return sum;
}

}  // namespace

namespace {

// cell_sum with derivatives (same draws, same truncation).
GaborSample cell_sample(const GaborParams& g, const GaborSetup& s, std::uint32_t seed, int cx,
                        int cy, double px, double py, double sigma2 = 0.0) {
  if (sigma2 > 0.0) return gabor_detail::cell_sample_filtered(g, s, seed, cx, cy, px, py, sigma2);
  GaborSample out;
  for_each_impulse(g, s, seed, cx, cy, px, py, [&](const Impulse& im) {
    const auto [dx, dy, amp, lambda, theta, psi, w, r2] = im;
    if (w <= 0.0 || r2 >= w * w * s.trunc_factor) return;
    // k = A E cos(P), E = exp(-r^2/W^2), P = f (d . o) + psi, f = 2 pi / lambda, o = (cos, sin).
    const double ox = std::cos(theta), oy = std::sin(theta), f = 2.0 * std::numbers::pi / lambda;
    const double e = amp * std::exp(-r2 / (w * w)), iw2 = 1.0 / (w * w);
    const double ph = f * (dx * ox + dy * oy) + psi, c = std::cos(ph), sn = std::sin(ph);
    out.f += e * c;
    out.fu += e * (-2.0 * dx * iw2 * c - sn * f * ox);
    out.fv += e * (-2.0 * dy * iw2 * c - sn * f * oy);
    out.fuv += e * (4.0 * dx * dy * iw2 * iw2 * c + 2.0 * dx * iw2 * sn * f * oy +
                    2.0 * dy * iw2 * sn * f * ox - c * f * f * ox * oy);
  });
  return out;
}

}  // namespace

int wrap_cell(int c, int period_cells) {
  if (period_cells <= 0) return c;
  const int half = period_cells / 2;
  return ((c + half) % period_cells + period_cells) % period_cells - half;
}

GaborBakePlan make_gabor_bake_plan(const GaborParams& g, const GaborSetup& s) {
  GaborBakePlan p;
  const double lambda_min = std::min(g.lambda_min_mm, g.lambda_max_mm);
  if (!(lambda_min > 0.0) || !(s.cell_mm > 0.0)) return p;
  const double max_texel = lambda_min / std::max(1, g.bake_samples_per_lambda);
  // Largest even N with N cells sampled at <= max_texel in at most kMaxBakeTexels samples.
  const double cells_fit = kMaxBakeTexels * max_texel / s.cell_mm;
  if (!(cells_fit >= 4.0)) return p;
  // The smallest even N whose period reaches kBakePeriodMm (bake time and memory grow with
  // N^2), at least 4 cells, at most what fits.
  const int fit = 2 * static_cast<int>(std::floor(cells_fit / 2.0));
  const int wanted = std::max(4, 2 * static_cast<int>(std::ceil(kBakePeriodMm / s.cell_mm / 2.0)));
  p.period_cells = std::min(fit, wanted);
  p.period_mm = p.period_cells * s.cell_mm;
  p.texels = std::min(kMaxBakeTexels, static_cast<int>(std::ceil(p.period_mm / max_texel)));
  p.texel_mm = p.period_mm / p.texels;
  p.ok = true;
  if (g.filter == GaborParams::Filter::kAnalytic) {
    const double lambda_max = std::max(g.lambda_min_mm, g.lambda_max_mm);
    // At the Hermite kappa (the smaller): a bilinear tile gets a level more than it needs.
    while (p.level_texels(p.filtered_levels + 1) >= 16 &&
           p.level_sigma2_mm2(p.filtered_levels) < lambda_max * lambda_max)
      ++p.filtered_levels;
  }
  return p;
}

GaborSample gabor_noise_derivatives(const GaborParams& g, const GaborSetup& s, std::uint32_t seed,
                                    double u, double v, int period_cells, double sigma2_mm2) {
  GaborSample sum;
  for_each_cell(s, u, v, 1, [&](int cx, int cy, double px, double py) {
    const GaborSample c =
        cell_sample(g, s, seed, wrap_cell(cx, period_cells), wrap_cell(cy, period_cells), px, py, sigma2_mm2);
    sum.f += c.f, sum.fu += c.fu, sum.fv += c.fv, sum.fuv += c.fuv;
  });
  return sum;
}

double gabor_noise_baked(const GaborParams& g, const GaborSetup& s, const GaborBakePlan& plan,
                         std::uint32_t seed, double u, double v) {
  const double h = plan.texel_mm;
  const double su = (u + 0.5 * plan.period_mm) / h, sv = (v + 0.5 * plan.period_mm) / h;
  const double iu = std::floor(su), iv = std::floor(sv), tu = su - iu, tv = sv - iv;
  const auto sample = [&](int a, int b) {  // (iu + a, iv + b), wrapped like GL_REPEAT / mod
    const double k = std::fmod(std::fmod(iu + a, plan.texels) + plan.texels, plan.texels);
    const double l = std::fmod(std::fmod(iv + b, plan.texels) + plan.texels, plan.texels);
    return gabor_noise_derivatives(g, s, seed, -0.5 * plan.period_mm + k * h, -0.5 * plan.period_mm + l * h,
                                   plan.period_cells);
  };
  if (plan.linear)
    return (1 - tu) * (1 - tv) * sample(0, 0).f + tu * (1 - tv) * sample(1, 0).f +
           (1 - tu) * tv * sample(0, 1).f + tu * tv * sample(1, 1).f;
  // Hermite basis: value weights h0 (t), h1 (1 - t); slope weights g0, g1 (per texel).
  const auto basis = [](double t, double w[4]) {
    w[0] = (1 + 2 * t) * (1 - t) * (1 - t);  // value at 0
    w[1] = t * t * (3 - 2 * t);              // value at 1
    w[2] = t * (1 - t) * (1 - t);            // slope at 0
    w[3] = -t * t * (1 - t);                 // slope at 1
  };
  double bu[4], bv[4];
  basis(tu, bu);
  basis(tv, bv);
  double f = 0.0;
  for (int b = 0; b < 2; ++b)
    for (int a = 0; a < 2; ++a) {
      const GaborSample x = sample(a, b);
      f += bu[a] * bv[b] * x.f + bu[2 + a] * bv[b] * x.fu * h + bu[a] * bv[2 + b] * x.fv * h +
           bu[2 + a] * bv[2 + b] * x.fuv * h * h;
    }
  return f;
}

double gabor_baked_rms_vs_naive(const GaborParams& g, const GaborSetup& s, const GaborBakePlan& plan,
                                std::uint32_t seed) {
  const double side = std::min(30.0, plan.period_mm - 2.0 * s.cell_mm);
  if (!plan.ok || !(side > 0.0)) return std::numeric_limits<double>::infinity();
  double sum2 = 0.0;
  constexpr int kN = 64;
  for (int j = 0; j < kN; ++j)
    for (int i = 0; i < kN; ++i) {
      const double u = side * ((i + 0.37) / kN - 0.5), v = side * ((j + 0.61) / kN - 0.5);
      const double e = (gabor_noise_baked(g, s, plan, seed, u, v) - gabor_noise(g, s, seed, u, v)) / s.sigma_unit;
      sum2 += e * e;
    }
  return std::sqrt(sum2 / (kN * kN));
}

namespace {
// The tiles "auto" tries, in order (fastest lookup first).
constexpr struct AutoTry { bool linear; int samples; } kAutoTries[] = {{true, 24}, {true, 32}, {false, 16}, {false, 32}};
}  // namespace

int smallest_auto_tile_texels(const GaborParams& g, const GaborSetup& s, double min_period_mm) {
  if (g.strategy != GaborParams::Strategy::kAuto) return 0;
  int smallest = 0;
  for (const AutoTry& t : kAutoTries) {
    GaborParams tried = g;
    tried.bake_samples_per_lambda = t.samples;
    const GaborBakePlan plan = make_gabor_bake_plan(tried, s);
    if (!plan.ok || plan.period_mm < min_period_mm) continue;
    if (smallest == 0 || plan.texels < smallest) smallest = plan.texels;
  }
  return smallest;
}

GaborStrategyChoice choose_gabor_tile(const GaborParams& g, const GaborSetup& s, std::uint32_t seed,
                                      double min_period_mm) {
  GaborStrategyChoice c;
  if (g.strategy == GaborParams::Strategy::kBaked || g.strategy == GaborParams::Strategy::kBakedLinear) {
    c.plan = make_gabor_bake_plan(g, s);
    c.plan.linear = g.strategy == GaborParams::Strategy::kBakedLinear;
    return c;
  }
  if (g.strategy != GaborParams::Strategy::kAuto) return c;
  for (const AutoTry& t : kAutoTries) {
    GaborParams tried = g;
    tried.bake_samples_per_lambda = t.samples;
    GaborBakePlan plan = make_gabor_bake_plan(tried, s);
    plan.linear = t.linear;
    if (!plan.ok) continue;
    c.best_period_mm = std::max(c.best_period_mm, plan.period_mm);
    if (plan.period_mm < min_period_mm) continue;  // a repeat inside one shadow
    c.rms_vs_naive = gabor_baked_rms_vs_naive(tried, s, plan, seed);
    if (c.rms_vs_naive <= kAutoBakeSelectRms) {
      c.plan = plan;
      return c;
    }
  }
  return c;
}

double gabor_noise(const GaborParams& g, const GaborSetup& s, std::uint32_t seed, double u,
                   double v) {
  double sum = 0.0;
  for_each_cell(s, u, v, 1, [&](int cx, int cy, double px, double py) { sum += cell_sum(g, s, seed, cx, cy, px, py); });
  return sum;
}

double gabor_noise_untruncated(const GaborParams& g, const GaborSetup& s, std::uint32_t seed,
                               double u, double v) {
  double sum = 0.0;
  // 2 cells = 2 W sqrt(-ln t): radius at which exp = t^4
  for_each_cell(s, u, v, 2, [&](int cx, int cy, double px, double py) {
    sum += cell_sum(g, s, seed, cx, cy, px, py, nullptr, 4.0 * s.trunc_factor);
  });
  return sum;
}

double gabor_truncation_margin(const GaborParams& g, const GaborSetup& s, std::uint32_t seed,
                               double u, double v) {
  double margin = std::numeric_limits<double>::infinity();
  for_each_cell(s, u, v, 1, [&](int cx, int cy, double px, double py) { cell_sum(g, s, seed, cx, cy, px, py, &margin); });
  return margin;
}

int gabor_cell_impulse_count(const GaborParams& g, const GaborSetup& s, std::uint32_t seed,
                             int cx, int cy) {
  std::uint32_t r = gabor_cell_seed(cx, cy, seed);
  return cell_count(g, s, r);
}

}  // namespace ps
