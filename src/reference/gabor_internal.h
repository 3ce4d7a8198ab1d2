// Internals of the Gabor CPU twin shared by gabor.cpp and gabor_filter.cpp: the impulses'
// draws, in the shader's order and float operations. Not part of the reference's interface.
#pragma once

#include <cmath>
#include <cstdint>

#include "reference/gabor.h"

namespace ps::gabor_detail {

// Impulses in a cell: the stratified count, or the naive draw of n / pi on average.
int cell_count(const GaborParams& g, const GaborSetup& s, std::uint32_t& r);

// The k-th impulse of a cell, relative to the point (px, py) in the cell's frame.
struct Impulse {
  double dx, dy, amp, lambda, theta, psi, w, r2;
};
int stratum_grid(const GaborSetup& s);
Impulse draw_impulse(const GaborParams& g, const GaborSetup& s, std::uint32_t& r, int k, int grid,
                     double px, double py);

// Calls f(impulse) for every impulse of cell (cx, cy), relative to (px, py) in the cell's frame,
// in draw order (every sum over a cell walks it this way, so all of them add in the same order).
template <class F>
void for_each_impulse(const GaborParams& g, const GaborSetup& s, std::uint32_t seed, int cx, int cy, double px,
                      double py, F&& f) {
  std::uint32_t r = gabor_cell_seed(cx, cy, seed);
  const int count = cell_count(g, s, r);
  const int grid = stratum_grid(s);
  for (int k = 0; k < count; ++k) f(draw_impulse(g, s, r, k, grid, px, py));
}

// Calls f(cx, cy, px, py) for the (2 reach + 1)^2 cells around (u, v), row by row from the lowest,
// with (px, py) the point relative to each cell.
template <class F>
void for_each_cell(const GaborSetup& s, double u, double v, int reach, F&& f) {
  const double fx = u / s.cell_mm, fy = v / s.cell_mm;
  const int cx = static_cast<int>(std::floor(fx)), cy = static_cast<int>(std::floor(fy));
  const double ox = (fx - cx) * s.cell_mm, oy = (fy - cy) * s.cell_mm;  // p relative to its cell
  for (int j = -reach; j <= reach; ++j)
    for (int i = -reach; i <= reach; ++i) f(cx + i, cy + j, ox - i * s.cell_mm, oy - j * s.cell_mm);
}

// The filtered kernels' value and derivatives in cell (cx, cy), footprint sigma2 I (gabor_filter.cpp).
GaborSample cell_sample_filtered(const GaborParams& g, const GaborSetup& s, std::uint32_t seed, int cx,
                                 int cy, double px, double py, double sigma2);

}  // namespace ps::gabor_detail
