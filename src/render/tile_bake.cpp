#include "render/tile_bake.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace ps {

namespace {
// A band is never thinner than this, so a tile of n rows is done within n / 8 frames however
// slow the machine (a 1596^2 tile: 200 frames at most).
constexpr int kMinSliceRows = 8;
}  // namespace

void TileBaker::add(size_t material, const GaborBlock& block, const GaborBakePlan& plan) {
  assert(plan.ok && "TileBaker::add: only ok plans are baked");
  jobs_.push_back({material, block, plan, {}, 0, 0});
  for (int level = 0; level <= plan.filtered_levels; ++level)
    total_texels_ += static_cast<long long>(plan.level_texels(level)) * plan.level_texels(level);
}

double TileBaker::progress() const {
  return total_texels_ == 0 ? 1.0 : static_cast<double>(baked_texels_) / static_cast<double>(total_texels_);
}

std::vector<TileBaker::Finished> TileBaker::take_finished() {
  std::vector<Finished> out;
  out.swap(finished_);
  return out;
}

Status TileBaker::bake_all(const std::string& glsl_root) {
  while (!jobs_.empty())
    if (Status s = bake_rows(glsl_root, jobs_.front(), jobs_.front().plan.texels); !s) return s;  // a whole level
  return ok_status();
}

double slice_budget_ms(double slice_ms, double last_frame_ms) {
  return std::clamp(last_frame_ms, slice_ms, kMaxSliceFactor * slice_ms);
}

Status TileBaker::bake_slice(const std::string& glsl_root, double last_frame_ms) {
  assert(params_.slice_ms > 0.0 && "TileBaker::bake_slice: slices need params.slice_ms > 0");
  if (jobs_.empty()) return ok_status();
  // The band's rows from the last band's rate (bake_rows finished its GPU work, so its wall time
  // is its time): the time per row is about constant within a tile. The first band is 16 rows.
  const double budget = slice_budget_ms(params_.slice_ms, last_frame_ms);
  if (rows_per_ms_ > 0.0)
    slice_rows_ = std::clamp(static_cast<int>(std::lround(rows_per_ms_ * budget)), kMinSliceRows, 1 << 16);
  const auto t0 = std::chrono::steady_clock::now();
  const Job& job = jobs_.front();
  const int rows = std::min(slice_rows_, job.plan.level_texels(job.level) - job.rows_done);
  if (Status s = bake_rows(glsl_root, jobs_.front(), rows); !s) return s;
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  rows_per_ms_ = rows / std::max(ms, 1e-3);
  return ok_status();
}

Status TileBaker::bake_rows(const std::string& glsl_root, Job& job, int rows) {
  const auto t0 = std::chrono::steady_clock::now();
  if (!pass_.ready()) {  // only renderers with a tile to bake build the bake program
    if (Status s = pass_.init(glsl_root); !s) return s;
  }
  if (job.rows_done == 0 && job.level == 0) job.tile = GaborBakePass::make_tile(job.plan);
  const int texels = job.plan.level_texels(job.level);
  const int end = std::min(texels, job.rows_done + rows);
  if (Status s = pass_.run_rows(job.tile, job.block, job.plan, job.rows_done, end, job.level); !s) return s;
  glFinish();  // llvmpipe draws on flush: finishing makes the wall time the band's time
  baked_texels_ += static_cast<long long>(end - job.rows_done) * texels;
  job.rows_done = end;
  bake_ms_ += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (job.rows_done == texels && job.level < job.plan.filtered_levels) {
    ++job.level;  // the next filtered level, from its first row
    job.rows_done = 0;
  } else if (job.rows_done == texels) {
    finished_.push_back({job.material, std::make_shared<gl::Texture>(std::move(job.tile))});
    jobs_.erase(jobs_.begin());  // job is jobs_.front(): callers bake the first job only
  }
  return ok_status();
}

}  // namespace ps
