// Analytic filtering of the Gabor texture (Lagae et al. 2009 §5): the CPU twin of the filtered
// kernels in glsl/lib/gabor.glsl (PS_GABOR_FILTER) and of the bake's filtered levels. The
// definitions are in gabor.h ("Analytic filtering").
#include <algorithm>
#include <cmath>
#include <numbers>

#include "reference/gabor.h"
#include "reference/gabor_internal.h"

namespace ps {

using namespace gabor_detail;

namespace {

// A kernel convolved with the Gaussian S (gabor.h, gabor_kernel_filtered):
// amp exp(-d^T Q d / 2) cos(k . d + psi), Q = C'^-1.
struct FilteredKernel {
  double amp, qxx, qxy, qyy, kx, ky;
};
FilteredKernel filter_kernel(double amp, double lambda, double theta, double w, const Cov2& S) {
  const double c = 0.5 * w * w;  // the envelope exp(-r^2/W^2) as a Gaussian of covariance c I
  const double a = c + S.xx, b = S.xy, d = c + S.yy, det = a * d - b * b;
  const double f = 2.0 * std::numbers::pi / lambda, k0x = f * std::cos(theta), k0y = f * std::sin(theta);
  FilteredKernel k;
  k.qxx = d / det, k.qxy = -b / det, k.qyy = a / det;
  k.kx = c * (k.qxx * k0x + k.qxy * k0y);
  k.ky = c * (k.qxy * k0x + k.qyy * k0y);
  // k'^T C' k' = c k0 . k', so the exponent is -(c |k0|^2 - c k0 . k') / 2.
  k.amp = amp * c / std::sqrt(det) * std::exp(-0.5 * c * (k0x * k0x + k0y * k0y - (k0x * k.kx + k0y * k.ky)));
  return k;
}

double cell_sum_filtered(const GaborParams& g, const GaborSetup& s, std::uint32_t seed, int cx, int cy,
                         double px, double py, const Cov2& S) {
  double sum = 0.0;
  for_each_impulse(g, s, seed, cx, cy, px, py, [&](const Impulse& im) {
    const auto [dx, dy, amp, lambda, theta, psi, w, r2] = im;
    if (w <= 0.0) return;
    const FilteredKernel f = filter_kernel(amp, lambda, theta, w, S);
    const double q = f.qxx * dx * dx + 2.0 * f.qxy * dx * dy + f.qyy * dy * dy;
    if (q >= 2.0 * s.trunc_factor) return;  // the filtered envelope below the truncation
    sum += f.amp * std::exp(-0.5 * q) * std::cos(f.kx * dx + f.ky * dy + psi);
  });
  return sum;
}

}  // namespace

Cov2 footprint_from_derivatives(double dudx, double dvdx, double dudy, double dvdy, double pixel_variance) {
  return {pixel_variance * (dudx * dudx + dudy * dudy), pixel_variance * (dudx * dvdx + dudy * dvdy),
          pixel_variance * (dvdx * dvdx + dvdy * dvdy)};
}

Cov2 cap_footprint(const Cov2& c, double cap) {
  const double m = 0.5 * (c.xx + c.yy), h = 0.5 * (c.xx - c.yy);
  const double rad = std::sqrt(h * h + c.xy * c.xy), l1 = m + rad, l2 = m - rad;
  if (l1 <= cap) return c;
  // Unit eigenvector of l1: (cos a, sin a) with tan 2a = 2 xy / (xx - yy).
  const double a = 0.5 * std::atan2(c.xy, h), e1x = std::cos(a), e1y = std::sin(a);
  const double m1 = std::min(l1, cap), m2 = std::min(l2, cap);
  return {m1 * e1x * e1x + m2 * e1y * e1y, (m1 - m2) * e1x * e1y, m1 * e1y * e1y + m2 * e1x * e1x};
}

double gabor_filter_need(double dudx, double dvdx, double dudy, double dvdy, double pixel_variance,
                         double lambda_min) {
  const double pi2 = std::numbers::pi * std::numbers::pi;
  return pi2 * pixel_variance * (dudx * dudx + dvdx * dvdx + dudy * dudy + dvdy * dvdy) / (lambda_min * lambda_min);
}

PixelSplit gabor_pixel_split(double dudx, double dvdx, double dudy, double dvdy, double pixel_variance,
                             double cap, int max_subsamples) {
  const bool x_major = dudx * dudx + dvdx * dvdx >= dudy * dudy + dvdy * dvdy;
  const double mu = x_major ? dudx : dudy, mv = x_major ? dvdx : dvdy;
  const double nu = x_major ? dudy : dudx, nv = x_major ? dvdy : dvdx;
  const double ratio = std::sqrt((mu * mu + mv * mv) / std::max(nu * nu + nv * nv, 1e-30));
  PixelSplit p;
  p.major_u = mu, p.major_v = mv;
  p.k = static_cast<int>(std::clamp(std::floor(ratio + 0.5), 1.0, std::max(1.0, static_cast<double>(max_subsamples))));
  p.S = cap_footprint(footprint_from_derivatives(nu, nv, mu / p.k, mv / p.k, pixel_variance), cap);
  return p;
}

double gabor_noise_pixel(const GaborParams& g, const GaborSetup& s, std::uint32_t seed, double u, double v,
                         double dudx, double dvdx, double dudy, double dvdy) {
  const PixelSplit p = gabor_pixel_split(dudx, dvdx, dudy, dvdy, g.filter_pixel_variance, footprint_cap_mm2(g),
                                         kGaborFilterMaxSubsamples);
  double sum = 0.0;
  for (int i = 0; i < p.k; ++i) {
    const double o = (i + 0.5) / p.k - 0.5;
    sum += gabor_noise_filtered(g, s, seed, u + o * p.major_u, v + o * p.major_v, p.S);
  }
  return sum / p.k;
}

double footprint_cap_mm2(const GaborParams& g) {
  const double w_min = g.kernel_periods * std::min(g.lambda_min_mm, g.lambda_max_mm);
  return kFootprintCapOfEnvelope * 0.5 * w_min * w_min;
}

double gabor_kernel(const GaborKernelShape& k, double dx, double dy) {
  const double phase = 2.0 * std::numbers::pi * (dx * std::cos(k.theta) + dy * std::sin(k.theta)) / k.lambda;
  return k.amp * std::exp(-(dx * dx + dy * dy) / (k.w * k.w)) * std::cos(phase + k.psi);
}

double gabor_kernel_filtered(const GaborKernelShape& k, double dx, double dy, const Cov2& S) {
  const FilteredKernel f = filter_kernel(k.amp, k.lambda, k.theta, k.w, S);
  const double q = f.qxx * dx * dx + 2.0 * f.qxy * dx * dy + f.qyy * dy * dy;
  return f.amp * std::exp(-0.5 * q) * std::cos(f.kx * dx + f.ky * dy + k.psi);
}

double gabor_noise_filtered(const GaborParams& g, const GaborSetup& s, std::uint32_t seed, double u,
                            double v, const Cov2& S) {
  double sum = 0.0;
  for_each_cell(s, u, v, 1, [&](int cx, int cy, double px, double py) {
    sum += cell_sum_filtered(g, s, seed, cx, cy, px, py, S);
  });
  return sum;
}

namespace gabor_detail {

// The filtered kernels' (gabor_noise_filtered) value and derivatives, S = sigma2 I:
// k = A E cos(P), E = exp(-d^T Q d / 2), P = k'.d + psi; with g = Q d:
// E_u = -g_u E, E_uv = (g_u g_v - Q_uv) E.
GaborSample cell_sample_filtered(const GaborParams& g, const GaborSetup& s, std::uint32_t seed, int cx,
                                 int cy, double px, double py, double sigma2) {
  GaborSample out;
  for_each_impulse(g, s, seed, cx, cy, px, py, [&](const Impulse& im) {
    const auto [dx, dy, amp, lambda, theta, psi, w, r2] = im;
    if (w <= 0.0) return;
    const FilteredKernel f = filter_kernel(amp, lambda, theta, w, Cov2{sigma2, 0.0, sigma2});
    const double gu = f.qxx * dx + f.qxy * dy, gv = f.qxy * dx + f.qyy * dy;
    const double q = dx * gu + dy * gv;
    if (q >= 2.0 * s.trunc_factor) return;
    const double e = f.amp * std::exp(-0.5 * q), ph = f.kx * dx + f.ky * dy + psi;
    const double c = std::cos(ph), sn = std::sin(ph);
    out.f += e * c;
    out.fu += e * (-gu * c - sn * f.kx);
    out.fv += e * (-gv * c - sn * f.ky);
    out.fuv += e * ((gu * gv - f.qxy) * c + gu * sn * f.ky + gv * sn * f.kx - c * f.kx * f.ky);
  });
  return out;
}

}  // namespace gabor_detail

}  // namespace ps
