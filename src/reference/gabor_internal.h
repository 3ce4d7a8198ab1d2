// Internals of the Gabor CPU twin shared by gabor.cpp and gabor_filter.cpp: the impulses'
// draws, in the shader's order and float operations. Not part of the reference's interface.
#pragma once

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

// The filtered kernels' value and derivatives in cell (cx, cy), footprint sigma2 I (gabor_filter.cpp).
GaborSample cell_sample_filtered(const GaborParams& g, const GaborSetup& s, std::uint32_t seed, int cx,
                                 int cy, double px, double py, double sigma2);

}  // namespace ps::gabor_detail
