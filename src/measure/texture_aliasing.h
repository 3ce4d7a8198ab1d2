// How far the Gabor texture a renderer draws is from what the eye would average over each pixel
// (docs/architecture.md, "Texture filtering"): the texture AOV of a small image against the same
// view rendered kSuper x kSuper larger and box-filtered down. Shared by the GL test
// (tests/measure/gabor_filter_gl_test.cpp) and `pseudoshadow bench --texture-filter`.
//
// The texture AOV (the Gabor value in sigmas) is compared, not the colour: inside the shadow the
// luminance is linear in it (pseudo_shadow_darkening: D = I + A s), and the AOV is that term
// alone, free of the shadow's own gradient, the gamma encoding and 8-bit rounding.
#pragma once

#include <memory>
#include <vector>

#include "core/result.h"
#include "image/image.h"
#include "scene/scene.h"

namespace ps {

class Renderer;

namespace aliasing {

inline constexpr int kSuper = 8;         // the reference's samples per pixel and axis
inline constexpr double kLambdaMm = 1.0;  // the texture's one wavelength

enum class View { kTopDown, kGrazing };

// A plane under a huge sphere (r = 500 mm, 0.5 mm above it) whose shadow covers every pixel of
// both views; the texture shows everywhere (onset and influence far beyond). One wavelength,
// every orientation, 10-20 impulses per kernel (like thesis Table 4.1 f). lambda_px: the
// wavelength in pixels at the centre of a size^2 image: top-down an orthographic view; grazing a
// perspective one (10-degree field of view) whose axis is 15 degrees above the plane, lambda_px
// measured across the view (the depth axis squeezes it by another sin 15 = 0.26).
// render_size: the size actually rendered (size, or size * kSuper for the reference).
Scene scene(View view, double lambda_px, int size, int render_size, GaborParams::Strategy strategy,
            GaborParams::Filter filter);

// The texture AOV of one frame of `s` (tiles shared with `reuse` where they match); an error
// when the shadow does not cover the whole view. keep: receives the renderer.
Result<Image> render_texture(const Scene& s, const Renderer* reuse = nullptr,
                             std::unique_ptr<Renderer>* keep = nullptr);

// `big` (kSuper * size per side) box-filtered down to size^2, row-major.
std::vector<double> box_down(const Image& big, int size);

struct Compare {
  double rms_over_sd = 0.0;  // RMS(test - reference) / sd(reference)
  double var_ratio = 0.0;    // var(test) / var(reference)
};
Compare compare(const Image& test, const std::vector<double>& reference);

}  // namespace aliasing
}  // namespace ps
