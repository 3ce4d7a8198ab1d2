// When the renderer's Gabor tiles are baked (GaborBakePass does the baking):
//   whole    (headless render, replay, tests, tune sweeps): every tile in Renderer::create, so
//            the first frame already reads it and every image is the one-shot image;
//   sliced   (the window): create() bakes nothing; before each frame one band of rows is baked,
//            of about as long as the last frame took (slice_budget_ms: at least slice_ms, at most
//            kMaxSliceFactor times it), and a material whose tile is unfinished draws with the
//            per-pixel Gabor sum (the same texture, within the tile's error: < 1 % sigma RMS for
//            "auto"). Frames come at about half their rate and the tile is ready in about twice
//            its whole bake, however slow the per-pixel frames are.
//            The first frame comes at once instead of after the whole bake (~1-2 s on llvmpipe)
//            and progress() tells the window how far the bake is.
// A texel's value does not depend on the band it was drawn in, so both give the same tiles.
// A tile's filtered levels (GaborBakePlan::filtered_levels) are baked after its level 0, band
// by band in the same way; the tile is finished when its last level is.
#pragma once

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "core/result.h"
#include "gl/objects.h"
#include "passes/gabor_bake.h"

namespace ps {

struct TileBakeParams {
  double slice_ms = 0.0;  // 0: whole tiles; > 0: bands of at least this much wall time per frame
};

// A band's wall time is at most this many times slice_ms, so a window whose per-pixel frames
// are very slow still answers a few times a second while it bakes.
inline constexpr double kMaxSliceFactor = 4.0;

// The wall time of the next band: the last frame's (`last_frame_ms`, 0 before the first frame),
// within [slice_ms, kMaxSliceFactor * slice_ms]. A band as long as a frame halves the frame rate
// while the tile bakes; a fixed band shorter than slow frames (Table 4.1's dense textures: 105 ms
// frames at 512^2 on one llvmpipe thread against 40 ms bands) left the tile 3.6 times its bake.
double slice_budget_ms(double slice_ms, double last_frame_ms);

class TileBaker {
 public:
  // One tile to bake for scene material `material`; block.tile must describe `plan`.
  void add(size_t material, const GaborBlock& block, const GaborBakePlan& plan);
  Status bake_all(const std::string& glsl_root);    // every tile left, whole
  // One band of about slice_budget_ms(params.slice_ms, last_frame_ms).
  Status bake_slice(const std::string& glsl_root, double last_frame_ms);
  // A finished tile per material that finished since the last call (then forgotten here).
  struct Finished {
    size_t material;
    std::shared_ptr<gl::Texture> tile;
  };
  std::vector<Finished> take_finished();

  bool done() const { return baked_texels_ == total_texels_; }
  double progress() const;                  // baked texels / texels to bake; 1 when none
  double bake_ms() const { return bake_ms_; }  // wall time spent baking, program build included
  void set_params(const TileBakeParams& p) { params_ = p; }
  const TileBakeParams& params() const { return params_; }

 private:
  struct Job {
    size_t material;
    GaborBlock block;
    GaborBakePlan plan;
    gl::Texture tile;   // allocated on its first band
    int level = 0;      // the mip level being baked (levels below it are done)
    int rows_done = 0;  // rows [0, rows_done) of that level are baked
  };
  // The next `rows` rows of `job` (clamped to the tile); job must be jobs_.front().
  Status bake_rows(const std::string& glsl_root, Job& job, int rows);

  TileBakeParams params_;
  GaborBakePass pass_;     // initialised on the first band
  std::vector<Job> jobs_;  // unfinished, in material order
  std::vector<Finished> finished_;
  long long total_texels_ = 0, baked_texels_ = 0;
  int slice_rows_ = 16;    // rows of the next band: 16 first, then fitted to the budget
  double rows_per_ms_ = 0.0;  // measured on the last band; 0 before the first
  double bake_ms_ = 0.0;
};

}  // namespace ps
