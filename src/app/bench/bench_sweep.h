// `pseudoshadow bench`: measurement side. Every configuration renders one analytic scene (a
// flat plane under an orthographic camera, a sphere probe sunk into it) so each error has a
// closed-form or CPU-reference answer on the same frame:
//   texture_rms_sigma  RMS of the GPU texture AOV minus the CPU Gabor reference of the same
//                      configuration (src/reference/gabor.h), in sigmas: the implementation
//                      error of the evaluation strategy;
//   texture_vs_ideal   RMS against the same impulses with untruncated kernels: the
//                      truncation error;
//   texture_vs_target  RMS against the baseline material's texture (n in [20, 30]): how far
//                      another impulse density moves the texture from the target one;
//   displacement_rel   |push along n - true penetration| / true penetration after one frame;
//   distance_max_mm    max |distance AOV - analytic sphere-plane distance| over the footprint;
//   normal_deg         reference normal vs the plane's normal.
// Timings: median over warm frames of the summed per-pass wall times (glFinish per pass).
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "core/result.h"
#include "scene/scene.h"

namespace ps::bench {

struct BenchOptions {
  int size = 512;          // image side, pixels
  int warm_frames = 2;     // discarded (shader JIT, caches)
  int timed_frames = 3;    // per round; the median is over all rounds' frames
  // The configurations are measured round-robin this many times, so load from other
  // processes on a shared machine spreads over all of them instead of skewing a few.
  int rounds = 3;
  std::function<void(const std::string&)> progress;  // one line per step; may be empty
};

struct Measurement {
  double frame_ms = 0.0, surface_ms = 0.0;
  // GL timer queries' frame (sum of the passes; docs/benchmarks.md, "GPU timers"): median over
  // the timed frames whose results came back; NaN: none did. In bench.md, not in bench.csv.
  double gpu_frame_ms = std::numeric_limits<double>::quiet_NaN();
  double texture_rms_sigma = 0.0, texture_vs_ideal = 0.0, texture_vs_target = 0.0;
  double displacement_rel = 0.0, distance_max_mm = 0.0, normal_deg = 0.0;
  int footprint_pixels = 0;
  std::vector<double> frame_samples, surface_samples;  // per timed frame, ms
};

struct BenchRow {
  std::string group, value;  // knob and its setting
  std::string metric;        // which error column is this group's error
  Measurement m;
  double error = 0.0;        // = the metric's value
  bool pareto = false;       // on the group's time-vs-error Pareto front
};

// Baseline bench scene at `size`^2 (flat plane, 60 mm ortho view, r = 25 mm probe 0.5 mm deep).
Scene bench_scene(int size);

// Renders `scene` (fresh renderer; needs a current GL context) and measures it.
Result<Measurement> measure(const Scene& scene, const BenchOptions& o);

// The accuracy knob sweep (reduction base resolution, depth map, Gabor n, truncation,
// strategy, displacement method); Pareto flags set per group.
Result<std::vector<BenchRow>> run_sweep(const BenchOptions& o);

// The pseudo-shadow frame of the default scene against the plain shading of the same view
// (probe out of reach), at size^2 (app/bench/bench_shadow_cost.cpp). Target: ratio <= 1.3.
struct ShadowCost {
  int size = 0;
  double shadow_frame_ms = 0.0, plain_frame_ms = 0.0, ratio = 0.0;  // medians; ratio of them
  double cpu_ratio = 0.0;  // the same for the process's CPU time per frame (all threads)
  std::vector<std::pair<std::string, double>> shadow_pass_ms;  // probe_depth, surface, reductions
  double plain_surface_ms = 0.0;
  unsigned shadow_pixels = 0;  // pixels inside the pseudo-shadow
  // The same medians from GL timer queries (gpu_timings_ms' frame); NaN: none came back.
  double gpu_shadow_frame_ms = std::numeric_limits<double>::quiet_NaN();
  double gpu_plain_frame_ms = std::numeric_limits<double>::quiet_NaN();
};
Result<ShadowCost> run_shadow_cost(const BenchOptions& o, int size);

// render.shadow_distance = "surface_normal" against "reference_plane" on one shipped scene at
// size^2, frames alternated in rounds (app/bench/bench_shadow_cost.cpp): what the distance along each
// point's own normal costs.
struct DistanceCost {
  std::string scene;
  int size = 0;
  double plane_frame_ms = 0.0, normal_frame_ms = 0.0, ratio = 0.0;        // medians; ratio of them
  double plane_surface_ms = 0.0, normal_surface_ms = 0.0, surface_ratio = 0.0;
  // surface_normal marched through the depth map (RendererOptions::closed_form_normal_distance
  // false: the mesh probe's way and the sphere's and capsule's before the closed form).
  double marched_frame_ms = 0.0, marched_ratio = 0.0;
  // The distance AOVs against surface_normal's closed form, over the pixels where both have a
  // probe above them (mm): how far the thesis's single plane is off on this scene, and the
  // march's error.
  double plane_vs_normal_max_mm = 0.0, plane_vs_normal_mean_mm = 0.0;
  double marched_vs_normal_max_mm = 0.0, marched_vs_normal_mean_mm = 0.0;
  long compared_pixels = 0;
};
Result<DistanceCost> run_distance_cost(const BenchOptions& o, const std::string& scene_path, int size);

// The default scene's frame with the thesis intensity formula against the same curve read from a
// lookup table (`table`, e.g. textures/intensity_thesis.lut: PS_INTENSITY_LUT) at size^2, frames
// alternated in rounds (app/bench/bench_shadow_cost.cpp): what reading a table costs.
struct LutCost {
  int size = 0;
  double formula_frame_ms = 0.0, lut_frame_ms = 0.0, ratio = 0.0;          // medians; ratio of them
  double formula_surface_ms = 0.0, lut_surface_ms = 0.0, surface_ratio = 0.0;
};
Result<LutCost> run_lut_cost(const BenchOptions& o, const std::string& table, int size);

struct SkipRatios {
  double beyond_influence = 0.0;  // frame with probe far / its plain shading (surface) pass
  double untextured = 0.0;        // PS_TEXTURED=0 frame / textured frame with no textured pixel
  double ms_per_kpx_footprint = 0.0;  // surface-pass slope vs textured footprint pixels
  double ms_per_kpx_screen = 0.0;     // surface-pass slope vs screen pixels, fixed footprint
  std::vector<ShadowCost> shadow_cost;  // at 512^2 and 1024^2
};
Result<SkipRatios> run_skip_ratios(const BenchOptions& o);

}  // namespace ps::bench
