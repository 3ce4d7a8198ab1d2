// Rendering a sweep: every cell through open_renderer + render, like `render`.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "prepare/prepare.h"
#include "scene/scene_io.h"
#include "render/scene_frames.h"
#include "tune/sweep.h"

namespace ps {

namespace {

struct CellInput {
  std::string scene_path;
  std::vector<std::string> overrides;
  std::vector<std::string> allow_paths;
};

CellInput cell_input(const SweepJob& job, const std::vector<std::size_t>& cell) {
  CellInput in{job.scene_path, job.overrides, job.allow_paths};
  for (std::size_t i = 0; i < job.axes.size(); ++i) {
    const std::string& v = job.axes[i].values[cell[i]];
    if (job.axes[i].key == kSceneAxisKey) in.scene_path = v;
    else in.overrides.push_back(job.axes[i].key + "=" + v);
  }
  return in;
}

Result<Scene> load_cell(const CellInput& in) { return load_scene_or_default(in.scene_path, in.overrides, in.allow_paths); }

// The scene loader names a bad override "--set KEY: ..."; in a sweep it came from --sweep.
Error as_sweep_error(const Error& e) {
  if (e.message.rfind("--set ", 0) == 0) return make_error("--sweep " + e.message.substr(6));
  return e;
}

}  // namespace

Status validate_sweep(const SweepJob& job) {
  auto count = sweep_cell_count(job.axes);
  if (!count) return count.error();
  // The scene and its --set overrides first, without any axis: a bad --set is blamed on --set,
  // not on the --sweep whose cells it breaks. (With a scene axis there is no one base scene.)
  const bool scene_axis = std::any_of(job.axes.begin(), job.axes.end(),
                                      [](const SweepAxis& a) { return a.key == kSceneAxisKey; });
  if (!scene_axis)
    if (auto base = load_cell({job.scene_path, job.overrides, job.allow_paths}); !base) return base.error();
  for (std::size_t i = 0; i < count.value(); ++i) {
    auto scene = load_cell(cell_input(job, sweep_cell(job.axes, i)));
    if (!scene) return as_sweep_error(scene.error());
  }
  return ok_status();
}

Result<std::vector<SweepCell>> render_sweep(const SweepJob& job, const SweepProgress& progress) {
  auto count = sweep_cell_count(job.axes);
  if (!count) return count.error();
  std::vector<SweepCell> cells;
  std::size_t mine = 0;
  for (std::size_t i = 0; i < count.value(); ++i) mine += job.shard.contains(i);
  for (std::size_t i = 0; i < count.value(); ++i) {
    if (!job.shard.contains(i)) continue;
    SweepCell cell;
    cell.index = sweep_cell(job.axes, i);
    cell.label = sweep_label(job.axes, cell.index);
    auto scene = load_cell(cell_input(job, cell.index));
    if (!scene) return as_sweep_error(scene.error());
    RendererOptions options = job.renderer;
    options.expected_frames = scene->render.frames;  // as `render` does, so a cell equals its render
    auto renderer = open_renderer(scene.value(), options);
    if (!renderer) return renderer.error();
    if (Status s = render_scene_frames(*renderer.value(), scene->render.frames); !s) return s.error();  // as `render`
    cell.image = renderer.value()->read_color();
    cell.stats = renderer.value()->stats();
    for (const auto& [name, ms] : cell.stats.timings_ms) cell.frame_ms += ms;
    cells.push_back(std::move(cell));
    if (progress) progress(cells.size(), mine, cells.back().label);
  }
  return cells;
}

Image sweep_sheet(const std::vector<SweepAxis>& axes, const std::vector<SweepCell>& cells) {
  ContactSheetDesc desc;
  const int n = static_cast<int>(cells.size());
  if (axes.size() > 1) {
    desc.columns = static_cast<int>(axes.back().values.size());
  } else {
    desc.columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
  }
  desc.thumb_width = cells.front().image.width;  // unscaled: a cell is the single render
  desc.label_scale = desc.thumb_width >= 320 ? 2 : 1;
  std::vector<Image> images;
  std::vector<std::string> labels;
  for (const auto& c : cells) {
    images.push_back(c.image);
    labels.push_back(c.label);
  }
  return contact_sheet(images, labels, desc);
}

std::string sweep_csv(const std::vector<SweepAxis>& axes, const std::vector<SweepCell>& cells) {
  std::string csv;
  for (const auto& a : axes) csv += a.key + ",";
  csv += "shadow_pixels,penetrating_pixels,max_penetration_mm,speed_gain,frame_ms\n";
  for (const auto& c : cells) {
    for (std::size_t i = 0; i < axes.size(); ++i) {
      std::string v = axes[i].values[c.index[i]];
      const bool quote = v.find(',') != std::string::npos || v.find('"') != std::string::npos;
      if (quote) {
        std::string q = "\"";
        for (char ch : v) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
        v = q + "\"";
      }
      csv += v + ",";
    }
    char buf[160];
    std::snprintf(buf, sizeof buf, "%u,%u,%.9g,%.9g,%.3f\n", c.stats.shadow_pixels, c.stats.penetrating_pixels,
                  c.stats.max_penetration_mm, c.stats.speed_gain, c.frame_ms);
    csv += buf;
  }
  return csv;
}

}  // namespace ps
