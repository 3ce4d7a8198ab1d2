// Reading the surface pass's targets back into images (the renderer's read_color / read_aov):
// the image-size region of a padded target, flipped to top row first.
#pragma once

#include <vector>

#include "core/result.h"
#include "gl/objects.h"
#include "image/image.h"
#include "passes/reductions.h"
#include "passes/surface.h"
#include "render/aov.h"

namespace ps {

// The w x h region at the origin of `tex` (4 channels; GL_UNSIGNED_BYTE scaled to [0, 1], else
// GL_FLOAT), top row first, with its first `channels_out` channels.
Image read_region(const gl::Texture& tex, int w, int h, int channels_out, GLenum format, GLenum type);

// The frame's colour (RGB, image size) and one AOV, as the last SurfacePass::run left them. The
// displacement AOV is drawn on request from the frame's targets (the frame itself uses row sums).
Image read_color_image(const SurfacePass& surface);
Result<Image> read_aov_image(const SurfacePass& surface, const ReductionsPass& reductions, Aov aov);
// Channel `channel` of the surface pass's AOV target into `out` (1 channel, image size, top row
// first; "no probe" outside shadow_rect()), through `raw`: both keep their storage, so a read
// every frame (the window's shadow measure) allocates nothing once they have grown.
void read_surface_aov_into(const SurfacePass& surface, int channel, Image& out, std::vector<float>& raw);
// read_aov_image into `out`: the surface AOVs through read_surface_aov_into (nothing allocated
// once the buffers have grown), the others as read_aov_image makes them.
Status read_aov_image_into(const SurfacePass& surface, const ReductionsPass& reductions, Aov aov, Image& out,
                          std::vector<float>& raw);

}  // namespace ps
