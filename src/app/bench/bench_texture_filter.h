// `pseudoshadow bench --texture-filter`: what the Gabor texture's analytic filtering costs and
// what it buys, in one run (docs/benchmarks.md, "Texture filtering"). For each view of
// measure/texture_aliasing.h (top-down and 15-degree grazing, lambda = 2 px) and each strategy
// (naive, baked_linear, baked), the unfiltered and the filtered texture: the frame's and the
// surface pass's median wall time (long-lived renderers, tiles baked at creation, frames
// alternated in rounds so load from other processes hits all alike) and the error against the
// view rendered 8 x 8 larger and box-filtered down (RMS / the reference's sd, variance ratio).
#pragma once

#include <string>

#include "app/bench/bench_sweep.h"
#include "core/result.h"

namespace ps::bench {

// The markdown table; needs a current GL context. size: the image side (the reference renders
// 8x that).
Result<std::string> run_texture_filter(const BenchOptions& o, int size);

}  // namespace ps::bench
