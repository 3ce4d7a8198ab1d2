// Parameter sweeps for `pseudoshadow tune`: axes of --set values, their cross product (the
// cells), and rendering every cell through the one Renderer path into a labelled contact sheet.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "core/result.h"
#include "image/image.h"
#include "image/text.h"
#include "render/renderer.h"

namespace ps {

// A sheet of more cells is refused: 256 cells of 128x128 already take minutes on llvmpipe.
inline constexpr std::size_t kMaxSweepCells = 256;
inline constexpr std::string_view kSceneAxisKey = "scene";  // the --sweep-scenes axis

struct SweepAxis {
  std::string key;                  // scene key (materials.wood.lambda_min) or "scene"
  std::vector<std::string> values;  // TOML values as text (or scene paths for "scene")
};

// "KEY=V1,V2,..." (commas inside [...] belong to the value) or "KEY=FROM:TO:STEPS" (STEPS
// evenly spaced numbers from FROM to TO inclusive, 2 <= STEPS <= kMaxSweepCells).
// Errors: "--sweep SPEC: ..." naming what is wrong (missing '=', empty value, STEPS, NaN).
Result<SweepAxis> parse_sweep(std::string_view spec);
// "a.toml,b.toml" -> the "scene" axis.
Result<SweepAxis> parse_scene_sweep(std::string_view list);

// Number of cells (product of the axis sizes), or an error above kMaxSweepCells.
Result<std::size_t> sweep_cell_count(const std::vector<SweepAxis>& axes);

// Cell `index` (row-major, the last axis varies fastest): one value index per axis.
std::vector<std::size_t> sweep_cell(const std::vector<SweepAxis>& axes, std::size_t index);
// "lambda_min=0.4 n_max=30" (the last component of each key; scene files by stem).
std::string sweep_label(const std::vector<SweepAxis>& axes, const std::vector<std::size_t>& cell);

// Shard `index` of `count` (from 1) of a sweep's cells: cells index-1, index-1+count, ...
// (round robin, so every shard gets a share of every axis). tune/sweep_shard.h.
struct ShardSpec {
  std::size_t index = 1, count = 1;
  bool contains(std::size_t cell) const { return cell % count == index - 1; }
};

struct SweepJob {
  std::string scene_path;                // empty: built-in default scene (unless a scene axis)
  std::vector<std::string> overrides;    // applied to every cell before the cell's values
  std::vector<SweepAxis> axes;
  RendererOptions renderer;
  ShardSpec shard;                       // render only this shard's cells (default: all)
  std::vector<std::string> allow_paths;  // --allow-path (scene/path_policy.h)
};

struct SweepCell {
  std::vector<std::size_t> index;
  std::string label;
  Image image;
  FrameStats stats;
  double frame_ms = 0.0;  // sum of the last frame's pass timings
};

// Loads (parses and validates) the base scene with its --set overrides (a bad one names the
// --set), then every cell's scene without rendering (a bad key or value names the --sweep). Runs before any GL work so errors come first and fast.
Status validate_sweep(const SweepJob& job);

using SweepProgress = std::function<void(std::size_t done, std::size_t total, const std::string& label)>;

// Renders every cell of job.shard (needs a current GL context); each cell: load_scene with the
// overrides, open_renderer, render.frames frames, read_color. `progress` after each cell
// (done and total count the shard's cells).
Result<std::vector<SweepCell>> render_sweep(const SweepJob& job, const SweepProgress& progress);

// Contact sheet with one column per value of the last axis; cells at their rendered size.
Image sweep_sheet(const std::vector<SweepAxis>& axes, const std::vector<SweepCell>& cells);

// CSV: one header line, then per cell its axis values and stats.
std::string sweep_csv(const std::vector<SweepAxis>& axes, const std::vector<SweepCell>& cells);

}  // namespace ps
