// Sparse-convolution Gabor noise (thesis §4.3.1; Lagae et al. 2009), double-precision CPU twin
// of glsl/lib/gabor.glsl. The random decisions (cell seeds, LCG draws, impulse counts) are bit-
// identical to the shader; only the kernel sums are evaluated in double.
//
// Definition (units: mm):
//   cell size C = kernel_periods * lambda_max * sqrt(-ln truncation)  (= the largest truncation
//   radius, so the 3x3 cells around a point hold every kernel that reaches it).
//   Per cell: LCG state from the cell index and seed (gabor_cell_seed: distinct for every cell
//   of a 65536-cell period); density n ~ U[n_min, n_max] impulses per kernel footprint;
//   count = min(cap, floor(n / pi + u)) (expected n/pi per C x C cell below the cap; a
//   stratified count instead of Lagae's Poisson: the mean and variance of the noise depend only
//   on the expected count because the random phases make cross terms vanish; sigma_unit uses
//   the expected count with the cap, expected_cell_count).
//   Per impulse, in this order: x, y ~ U[0,C); A ~ U[a_min,a_max]; lambda ~ U[lmin,lmax];
//   theta ~ U[tmin,tmax]; psi ~ U[0, 2pi).
//   Stratified strategy (GaborParams::Strategy::kStratified): count = min(cap, K) fixed, no
//   density draws; impulse k sits in stratum (k mod g, k div g) of a g x g grid over the
//   cell, g = ceil(sqrt(K)), jittered by the same x, y draws; same A, lambda, theta, psi draws.
//   Kernel: A exp(-r^2/W^2) cos(2pi (dx cos(theta) + dy sin(theta)) / lambda + psi),
//   W = kernel_periods * lambda, cut to 0 where exp(-r^2/W^2) < truncation.
#pragma once

#include <cstdint>

#include "scene/scene.h"

namespace ps {

inline constexpr std::uint32_t kLcgMultiplier = 3039177861u;  // thesis §4.5.2, Lagae et al.

// Derived per-material constants shared by the shader uniforms and the reference.
struct GaborSetup {
  double cell_mm = 1.0;
  double trunc_factor = 3.0;  // -ln(truncation): kernel cut at r^2 < W^2 * trunc_factor
  double sigma_unit = 1.0;    // std-dev of the noise with A == 1: exact for the counts drawn (gabor.cpp)
  int max_impulses = 64;
  // Stratified strategy: this many impulses in every cell (0 = naive random count), one per
  // stratum of a g x g grid, g = ceil(sqrt(count)).
  int stratified_count = 0;
};

GaborSetup make_gabor_setup(const GaborParams& g);

// Baked strategy: the tile holding one period of the periodic texture. Sample points
// u_i = -period/2 + i * texel (i = 0 .. texels-1) on both axes; texel <= lambda_min /
// bake_samples_per_lambda (default 16). Bicubic Hermite interpolation of a sinusoid errs by
// (2 pi / 16)^4 / 384 = 6e-5 of its amplitude there; what remains is the truncation
// circles, where the texture jumps by up to truncation x A and the interpolation smears it
// over one texel (RMS ~ sqrt(texel)). period = period_cells * cell, period_cells even and >= 4, as large as
// kMaxBakeTexels allows. ok == false: the material is too fine for a tile of that size
// (lambda_max / lambda_min too large) and the naive evaluation is used instead.
inline constexpr int kMaxBakeTexels = 2048;  // per side: 64 MiB of RGBA32F at most
// Wanted period: wider than any probe footprint we ship (the bench's r = 25 mm sphere covers
// 50 mm), so one footprint never shows a repeat.
inline constexpr double kBakePeriodMm = 64.0;
// Filtered levels (GaborParams::Filter::kAnalytic): mip level L = 1 .. filtered_levels of the
// tile holds texels >> L samples per side (texel h_L = period / (texels >> L)) of the texture
// filtered analytically with an isotropic Gaussian of standard deviation kappa * h_L
// (gabor_noise_derivatives with sigma2_mm2), never box-averaged texels. Level 0 is the
// unfiltered tile. Levels stop at 16 texels per side or once sigma_L (at the Hermite kappa)
// passes lambda_max (the texture is then attenuated to exp(-2 pi^2) of itself).
// kappa = sigma_L / h_L: a level's content must stay smooth on its own grid for the
// interpolation. A bilinear lookup errs by at most (2 pi f h)^2 / 8 exp(-2 pi^2 k^2 h^2 f^2) of
// a sinusoid's amplitude, whose maximum over f is 1 / (4 e k^2): 2.3 % at k = 2; the Hermite
// lookup by (2 pi f h)^4 / 384 exp(...), at most 4 / (384 e^2 k^4) = 0.56 % at k = 1. A smaller
// kappa puts the first filtered level nearer the unfiltered one: between the two the lookup
// blends them, and the unfiltered share aliases (measured: kappa 2 left the Hermite tile at
// 0.37 sd from the reference at lambda = 1.5 px, kappa 1 at <= 0.2).
inline constexpr double kBakeLevelSigmaTexelsLinear = 2.0;
inline constexpr double kBakeLevelSigmaTexelsHermite = 1.0;
struct GaborBakePlan {
  bool ok = false;
  bool linear = false;  // values only, bilinear lookup (strategy baked_linear); else Hermite
  int period_cells = 0;
  int texels = 0;
  double period_mm = 0.0, texel_mm = 0.0;
  int filtered_levels = 0;  // mip levels 1 .. filtered_levels (0: the unfiltered level alone)
  int level_texels(int level) const { return texels >> level; }
  double level_texel_mm(int level) const { return period_mm / level_texels(level); }
  double level_sigma_texels() const { return linear ? kBakeLevelSigmaTexelsLinear : kBakeLevelSigmaTexelsHermite; }
  // Variance (mm^2) of the isotropic filter level L was baked with (0 at level 0).
  double level_sigma2_mm2(int level) const {
    const double s = level == 0 ? 0.0 : level_sigma_texels() * level_texel_mm(level);
    return s * s;
  }
};
GaborBakePlan make_gabor_bake_plan(const GaborParams& g, const GaborSetup& s);

// RMS of (baked - naive) / sigma over 64 x 64 off-grid points of the central period (a square
// of side min(30 mm, period - 2 cells) at the origin): the method's error, in double.
double gabor_baked_rms_vs_naive(const GaborParams& g, const GaborSetup& s, const GaborBakePlan& plan,
                                std::uint32_t seed);

// The tile a material gets: strategy kBaked / kBakedLinear -> its bake_samples_per_lambda as
// asked (no error check); kAuto -> bilinear at 24 and 32, then Hermite at 16 and 32 samples per
// lambda_min (fastest lookup first, bench-measured), the first whose measured RMS against the
// naive texture is <= kAutoBakeSelectRms and whose period is >= min_period_mm; otherwise (and for
// other strategies) ok == false. The renderer passes the pseudo-shadow window's width (the probe's
// bounding diameter) as min_period_mm, so "auto" never shows a repeat inside one shadow.
// Sigma. The bar a tile must meet is 1 % RMS; what the estimate must show is lower: the error
// sits on sparse truncation circles, so an RMS from a few thousand points scatters by ~10-20 %
// between point sets (sparse textures most); a tile chosen at 0.99 % measured 1.27 % on another
// set. 0.9 % leaves that margin.
inline constexpr double kAutoBakeSelectRms = 0.009;
struct GaborStrategyChoice {
  GaborBakePlan plan;          // ok: bake this; else evaluate naive (or stratified)
  double rms_vs_naive = -1.0;  // measured when kAuto considered a tile (last one tried)
  double best_period_mm = 0.0; // kAuto: the longest period a tile could have had
};
// The side (texels) of the smallest tile "auto" could pick with a period >= min_period_mm,
// without measuring any tile's error (cheap: plans only); 0 if it could pick none or the
// strategy is not "auto". A lower bound on the bake a renderer would pay.
int smallest_auto_tile_texels(const GaborParams& g, const GaborSetup& s, double min_period_mm);
GaborStrategyChoice choose_gabor_tile(const GaborParams& g, const GaborSetup& s, std::uint32_t seed,
                                      double min_period_mm = 0.0);

// Cell index wrapped into [-N/2, N/2) for a period of N cells (N = 0: unchanged).
int wrap_cell(int c, int period_cells);

// Value and derivatives of the noise at (u, v): x = f, y = df/du, z = df/dv, w = d2f/dudv
// (per mm). period_cells > 0: the periodic texture (cells hashed by wrap_cell), else the naive
// one. The baked tile stores these at its sample points.
struct GaborSample {
  double f = 0.0, fu = 0.0, fv = 0.0, fuv = 0.0;
};
// sigma2_mm2 > 0: of the texture filtered with an isotropic Gaussian of that variance (the
// tile's filtered levels, GaborBakePlan::level_sigma2_mm2).
GaborSample gabor_noise_derivatives(const GaborParams& g, const GaborSetup& s, std::uint32_t seed,
                                    double u, double v, int period_cells, double sigma2_mm2 = 0.0);

// CPU twin of the baked lookup: bicubic Hermite (plan.linear: bilinear) interpolation of the tile's samples (computed
// here in double with gabor_noise_derivatives) at (u, v). Its difference from
// gabor_noise_derivatives(...).f is the interpolation error alone.
double gabor_noise_baked(const GaborParams& g, const GaborSetup& s, const GaborBakePlan& plan,
                         std::uint32_t seed, double u, double v);

// ---- Analytic filtering (Lagae et al. 2009 §5) ----
// A symmetric 2x2 covariance in (u, v), mm^2: the pixel footprint's Gaussian.
struct Cov2 {
  double xx = 0.0, xy = 0.0, yy = 0.0;
};
// The footprint of a pixel whose (u, v) changes by du_dx (one pixel right) and du_dy (one pixel
// down): pixel_variance * (du_dx du_dx^T + du_dy du_dy^T), pixel_variance in pixels^2.
Cov2 footprint_from_derivatives(double dudx, double dvdx, double dudy, double dvdy, double pixel_variance);
// Each eigenvalue of `c` capped at `cap` mm^2 (same eigenvectors). The filtered kernels are
// evaluated from the 3x3 cells around the point like the unfiltered ones; a footprint wider
// than the kernels would need more cells. Along a kernel's frequency a footprint of variance
// W^2/2 already attenuates it to exp(-pi^2 kernel_periods^2 / 2) (< 1 % at 1 period), so the
// cap kFootprintCapOfEnvelope * W_min^2 / 2 loses nothing visible there; across the
// frequency it leaves the envelope's own slow modulation under-filtered.
inline constexpr double kFootprintCapOfEnvelope = 1.0;
Cov2 cap_footprint(const Cov2& c, double cap);
double footprint_cap_mm2(const GaborParams& g);

// A pixel's box split into k sub-boxes along its longer screen axis, k = its anisotropy
// rounded, at most kGaborFilterMaxSubsamples: sub-box i centred at (u, v) + major ((i + 0.5) / k
// - 0.5), each a Gaussian of covariance pixel_variance (minor minor^T + major major^T / k^2),
// capped. One Gaussian standing for a long, thin box leaks what the box kills (about one cycle
// per pixel along it) and that aliases; k Gaussians each 1/k as long follow the box out to k
// cycles per pixel (measured at a 15-degree grazing view: 0.47 sd from the supersampled
// reference with one, <= 0.3 with four). A 15-degree view is 3.9x anisotropic: 4 covers it.
inline constexpr int kGaborFilterMaxSubsamples = 4;
struct PixelSplit {
  double major_u = 0.0, major_v = 0.0;  // the longer screen axis's (u, v) step over the pixel, mm
  int k = 1;
  Cov2 S;
};
// dudx, dvdx: (u, v) change one pixel right; dudy, dvdy: one pixel down (or up: signs do not
// matter).
PixelSplit gabor_pixel_split(double dudx, double dvdx, double dudy, double dvdy, double pixel_variance,
                             double cap, int max_subsamples);
// How much the analytic filter would attenuate lambda_min over that pixel: the exponent
// 2 pi^2 s2 / lambda_min^2 for the footprint's mean variance s2 = pixel_variance (|du/dx|^2 +
// |du/dy|^2) / 2 before the split and the cap (which only lower it). The surface pass writes
// it where it evaluates a filtered texture; below kGaborFilterNegligibleNeed over a whole frame
// the next frame skips the filter (render/renderer.h). GLSL twin: gabor_filter_need.
double gabor_filter_need(double dudx, double dvdx, double dudy, double dvdy, double pixel_variance,
                         double lambda_min);
// The texture filtered over that pixel (the surface pass's PS_GABOR_FILTER variant).
double gabor_noise_pixel(const GaborParams& g, const GaborSetup& s, std::uint32_t seed, double u, double v,
                         double dudx, double dvdx, double dudy, double dvdy);

// One Gabor kernel A exp(-r^2/W^2) cos(2 pi d.o / lambda + psi), untruncated, at offset
// d = (dx, dy) from its impulse; and the same kernel convolved with the normalised Gaussian of
// covariance S. The convolution is again a Gabor kernel (complex form: a Gaussian times a
// complex sinusoid; in frequency space the product of two Gaussians): with C = (W^2/2) I the
// kernel's envelope covariance, C' = C + S,
//   envelope exp(-d^T C'^-1 d / 2), frequency k' = C'^-1 C k0 (k0 = 2 pi o / lambda),
//   amplitude A sqrt(|C| / |C'|) exp(-(k0^T C k0 - k'^T C' k') / 2), phase psi unchanged.
struct GaborKernelShape {
  double amp = 1.0, lambda = 1.0, theta = 0.0, psi = 0.0, w = 1.0;
};
double gabor_kernel(const GaborKernelShape& k, double dx, double dy);
double gabor_kernel_filtered(const GaborKernelShape& k, double dx, double dy, const Cov2& S);

// The noise filtered with the footprint S (mm^2): every kernel of gabor_noise filtered as
// above, cut where its filtered envelope falls below the truncation (so S = 0 gives
// gabor_noise). S is used as given (cap it with cap_footprint as the shader does).
double gabor_noise_filtered(const GaborParams& g, const GaborSetup& s, std::uint32_t seed, double u,
                            double v, const Cov2& S);

// Cell seeds (the LCG's first state in each cell). The cell packs into a 32-bit key,
// key = (cx mod 2^16) | (cy mod 2^16) << 16, so the texture repeats every 65536 cells on each
// axis (at C = 10 mm, 655 m). The key is hashed with murmur3's finaliser fmix32 (a bijection
// of 32-bit words): state = fmix32(fmix32(key) ^ fmix32(seed + kGaborSeedOffset)). For each
// material seed that is a bijection of the keys, so every cell of the period gets its own
// state, except that the one state 0 (which would stall the multiplicative LCG) is replaced by
// the state of the cell (cx + 32768, cy + 32768): any window of up to 32768 x 32768 cells has
// no two cells alike. Mixing the key before the seed keeps two material seeds from being the
// same cells shuffled in blocks (as key ^ m would) or translated (as key + m would).
inline constexpr std::uint32_t kGaborSeedOffset = 0x9e3779b9u;    // 2^32 / golden ratio
inline constexpr std::uint32_t kGaborHalfPeriodKey = 0x80008000u;  // +32768 cells on both axes
std::uint32_t fmix32(std::uint32_t h);
std::uint32_t gabor_cell_seed(int cx, int cy, std::uint32_t seed);
// The expected impulse count of a cell, E[min(count, cap)], exactly (gabor.cpp): the density
// sigma_unit is normalised with.
double expected_cell_count(const GaborParams& g, const GaborSetup& s);
// One LCG step, then the new state mapped to [0, 1] in float (as the shader does).
float lcg_uniform(std::uint32_t& state);

// Raw noise value at (u, v) in mm (A included, not normalised).
double gabor_noise(const GaborParams& g, const GaborSetup& s, std::uint32_t seed, double u,
                   double v);

// The same impulses with untruncated kernels (5x5 cells: kernels are still cut where
// exp(-r^2/W^2) < truncation^4, i.e. below 6e-6 A at truncation 0.05): the ideal noise that
// the truncation approximates, for measuring the truncation error.
double gabor_noise_untruncated(const GaborParams& g, const GaborSetup& s, std::uint32_t seed,
                               double u, double v);

// Smallest |r - W sqrt(-ln truncation)| (mm) over the kernels evaluated at (u, v): how close
// the point lies to a truncation circle, where the noise jumps by up to truncation * |A|. Tests
// use it to tell float32 position rounding across a cut from real errors.
double gabor_truncation_margin(const GaborParams& g, const GaborSetup& s, std::uint32_t seed,
                               double u, double v);

// Number of impulses generated for one cell (for tests of the count rule and the cap).
int gabor_cell_impulse_count(const GaborParams& g, const GaborSetup& s, std::uint32_t seed,
                             int cx, int cy);

}  // namespace ps
