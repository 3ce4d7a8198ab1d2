// Float images in memory and their files. PNG is read and written with libpng; every other format
// (EXR, anything OpenImageIO reads) goes through OpenImageIO in the module libps_image_oiio.so,
// loaded on first use, so PNG-only processes never map OpenImageIO's ~270 libraries.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "core/output_set.h"
#include "core/result.h"

namespace ps {

// Row 0 is the TOP row (file order). Pixel values are floats; 8-bit files map to [0,1].
struct Image {
  int width = 0, height = 0, channels = 0;
  std::vector<float> pixels;  // width * height * channels, interleaved
  // 8 when read from a file of 8-bit integer samples (values are exactly k/255 up to float
  // rounding), else 0 (float or 16-bit files, images made in memory). compare_images compares
  // two 8-bit images in whole levels.
  int file_bits = 0;

  float& at(int x, int y, int c) { return pixels[(static_cast<size_t>(y) * width + x) * channels + c]; }
  float at(int x, int y, int c) const { return pixels[(static_cast<size_t>(y) * width + x) * channels + c]; }
};

// PNG (recognised by its signature, whatever the extension): palette expands to RGB, tRNS to
// alpha, low-bit gray to 8 bit; channels as in the file (gray 1, gray+alpha 2, RGB 3, RGBA 4);
// 8- and 16-bit samples map to [0,1]. Other files: whatever OIIO reads, as float. Colour is read
// as stored (never premultiplied). Errors name the path and are one line.
Result<Image> read_image(const std::string& path);
// Writes PNG (8 bit, clamped to [0,1], rounded, NaN as 0; 1 to 4 channels) or EXR (32-bit float)
// by extension; other extensions go to whatever OIIO writes for them. Written to a temp file
// and renamed into place (core/file_io.h) so a crash never leaves a half-written file; follows
// the output directory rule (only a missing last directory is created). Errors name the path;
// sizes outside 1..16384 are refused; a non-PNG file whose module cannot be loaded is an error
// saying which paths were tried.
Status write_image(const std::string& path, const Image& image);
// As write_image, but as one output of `outputs`: published by outputs.publish() together with
// the command's other files, or not at all.
Status stage_image(OutputSet& outputs, const std::string& path, const Image& image);

// Thresholds are on the [0,1] scale. When both images are 8-bit files (Image::file_bits == 8)
// the comparison is in whole levels: each value becomes round(v*255), each threshold
// round(T*255) levels (0.004 -> 1, 0.0078 -> 2), so "one 8-bit step" means exactly that and
// float rounding of k/255 never decides a pass. Otherwise values compare as floats.
struct CompareOptions {
  float fail_threshold = 1.0f / 255.0f;  // a pixel fails if any channel differs by more
  double fail_percent = 0.0;             // the comparison fails if more than this % of pixels fail
  // Hard cap (OIIO idiff -hardfail): the comparison fails if any channel of any pixel differs by
  // more than this, whatever fail_percent allows. Infinity = no cap.
  float hard_fail_threshold = std::numeric_limits<float>::infinity();
};

struct CompareResult {
  bool passed = false;
  double max_abs = 0.0;        // largest channel difference
  bool in_levels = false;      // both images were 8-bit: differences counted in whole levels
  int max_levels = 0;          // largest difference in levels (when in_levels)
  long hard_failing_pixels = 0;  // pixels beyond hard_fail_threshold
  double mean_abs = 0.0;       // mean channel difference
  long failing_pixels = 0;
  double failing_percent = 0.0;
  Image diff;                  // |a-b| per channel, amplified x10 and clamped for viewing; alpha
                               // (2 or 4 channels) is opaque, its difference folded into colour
};

// Errors: unreadable file, size or channel-count mismatch.
Result<CompareResult> compare_images(const Image& a, const Image& b, const CompareOptions& options);

}  // namespace ps
