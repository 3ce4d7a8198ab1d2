// When the renderer's Gabor tiles are baked (GaborBakePass does the baking):
//   whole    (headless render, replay, tests, tune sweeps): every tile in Renderer::create, so
//            the first frame already reads it and every image is the one-shot image;
//   sliced   (the window): create() bakes nothing; before each frame one band of rows of about
//            slice_ms is baked, and a material whose tile is unfinished draws with the per-pixel
//            Gabor sum (the same texture, within the tile's error: < 1 % sigma RMS for "auto").
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
  double slice_ms = 0.0;  // 0: whole tiles; > 0: bands of about this much wall time per frame
};

class TileBaker {
 public:
  // One tile to bake for scene material `material`; block.tile must describe `plan`.
  void add(size_t material, const GaborBlock& block, const GaborBakePlan& plan);
  Status bake_all(const std::string& glsl_root);    // every tile left, whole
  Status bake_slice(const std::string& glsl_root);  // one band of about params.slice_ms
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
  int slice_rows_ = 16;    // rows of the next band: 16 first, then fitted to slice_ms
  double bake_ms_ = 0.0;
};

}  // namespace ps
