// `pseudoshadow bench --moving` (docs/benchmarks.md, "Moving views"): frames while the view moves
// (a camera orbit on the default scene, a travel through Field, a turn of the rolling flat torus),
// drawn whole and at the adaptive scale (render/adaptive_scale.h) by two renderers of the same
// view, frame by frame in turn, so that load from other processes hits both alike. Reports the
// frame p50/p99 of each, the scales used, the rest frame's delay, the image error of the
// adaptive frames against the whole ones (RMS, and the pseudo-shadow's darkness along a row
// through it) and the per-pass split of the whole frames.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "core/result.h"
#include "scene/scene.h"

namespace ps::bench {

struct MovingOptions {
  std::vector<glm::ivec2> sizes{{1280, 720}, {1920, 1080}};
  int frames = 90;           // moving frames per case and size (1.5 s of motion at 60 frames a second)
  int error_every = 10;      // the image error is read back every this many frames (outside the timing)
  double budget_ms = 16.7;   // AdaptiveScaleParams::budget_ms
  std::function<void(const std::string&)> progress;
};

struct MovingRow {
  std::string motion;  // orbit, travel, turn
  std::string scene;
  glm::ivec2 size{0};
  double full_p50_ms = 0.0, full_p99_ms = 0.0;
  double adaptive_p50_ms = 0.0, adaptive_p99_ms = 0.0;
  double scale_min = 1.0, scale_median = 1.0;  // over the adaptive moving frames
  double rest_ms = 0.0;       // from the last move to the end of the first whole frame at rest
  bool rest_equal = false;    // the settled rest frame equals the whole renderer's bit for bit
  double rms_levels = 0.0;    // colour RMS error of the adaptive motion frames, 8-bit levels (mean)
  double profile_max_levels = 0.0;  // largest luminance difference along the row through the shadow
  // Whole frames' per-pass medians (CPU wall, glFinish per pass), and the adaptive frames'.
  std::vector<std::pair<std::string, double>> full_passes, adaptive_passes;
  std::vector<double> full_frames, adaptive_frames, scales;  // per moving frame (the plot)
};

// The camera turned `degrees` about its target, around its up: a mouse drag's orbit (the
// scripted motion of `bench --moving` and of `bench-haptics --orbit`).
Camera orbited(const Camera& camera, double degrees);

Result<std::vector<MovingRow>> run_moving(const MovingOptions& o);
// Markdown: the frame table, then the per-pass split.
std::string moving_markdown(const std::vector<MovingRow>& rows, const MovingOptions& o);
// One line per moving frame: motion, size, frame, full_ms, adaptive_ms, scale.
std::string moving_csv(const std::vector<MovingRow>& rows);

}  // namespace ps::bench
