// Pixel comparison for golden tests: per-channel absolute differences, a per-pixel threshold and a
// failing-pixel budget (Filament renderdiff / OSL testsuite style), plus an amplified diff image.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "image/image.h"

namespace ps {
namespace {

// Differences of a few 1/255 steps are invisible at x1; x10 makes a one-step error ~4 % grey.
constexpr float kDiffGain = 10.0f;
constexpr int kMaxChannels = 64;  // same limit as read_image/write_image

std::string size_text(const Image& image) {
  return std::to_string(image.width) + "x" + std::to_string(image.height) + "x" +
         std::to_string(image.channels);
}

// |a-b|, where a NaN on one side only counts as an infinite difference (it must fail) and NaN on
// both sides counts as equal (the golden recorded the same NaN).
double channel_diff(float a, float b) {
  const bool nan_a = std::isnan(a), nan_b = std::isnan(b);
  if (nan_a || nan_b) return nan_a && nan_b ? 0.0 : std::numeric_limits<double>::infinity();
  if (a == b) return 0.0;  // also makes inf == inf a zero difference instead of NaN
  return std::fabs(static_cast<double>(a) - static_cast<double>(b));
}

// A value read from an 8-bit file is k * (1/255.f); rounding v*255 in double gives k back exactly.
int level(float v) { return static_cast<int>(std::lround(static_cast<double>(std::clamp(v, 0.0f, 1.0f)) * 255.0)); }

// A [0,1] threshold in whole levels, rounded to nearest: 1/255 and 0.004 -> 1, 0.0078 -> 2.
// Rounding (not flooring) keeps a threshold written to 4 decimals meaning the level it is
// closest to. Infinity (no cap) stays infinite.
double to_levels(float threshold) {
  if (!std::isfinite(threshold)) return std::numeric_limits<double>::infinity();
  return static_cast<double>(std::lround(static_cast<double>(threshold) * 255.0));
}

struct Limits {
  double fail, hard_fail;  // a channel difference beyond these fails the pixel / the comparison
};

// Gray+alpha (2) and RGBA (4) images carry alpha last. The diff image keeps that channel but makes
// it opaque, otherwise viewers show an all-transparent picture wherever alpha matches; an alpha
// difference is folded into the colour channels instead so it stays visible.
bool has_alpha(int channels) { return channels == 2 || channels == 4; }

void write_diff_pixel(const double* d, int channels, float* out) {
  const bool alpha = has_alpha(channels);
  const int colours = alpha ? channels - 1 : channels;
  const double alpha_diff = alpha ? d[channels - 1] : 0.0;
  for (int c = 0; c < colours; ++c) {
    out[c] = static_cast<float>(std::min(1.0, std::max(d[c], alpha_diff) * kDiffGain));
  }
  if (alpha) out[channels - 1] = 1.0f;
}

// Same size and channels, not empty, at most kMaxChannels, buffers of that size.
Status check_comparable(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels) {
    return make_error("image sizes differ: " + size_text(a) + " vs " + size_text(b) +
                      " (width x height x channels)");
  }
  const size_t pixel_count = static_cast<size_t>(a.width) * a.height;
  if (pixel_count == 0 || a.channels <= 0 || a.channels > kMaxChannels ||
      a.pixels.size() != pixel_count * a.channels || b.pixels.size() != a.pixels.size()) {
    return make_error("cannot compare images of " + size_text(a) +
                      ": empty, too many channels, or pixel buffer size does not match");
  }
  return ok_status();
}

}  // namespace

Result<CompareResult> compare_images(const Image& a, const Image& b, const CompareOptions& options) {
  if (Status st = check_comparable(a, b); !st) return st.error();
  const size_t pixel_count = static_cast<size_t>(a.width) * a.height;
  CompareResult result;
  result.diff.width = a.width;
  result.diff.height = a.height;
  result.diff.channels = a.channels;
  result.diff.pixels.resize(a.pixels.size());
  const int channels = a.channels;
  const bool levels = a.file_bits == 8 && b.file_bits == 8;
  result.in_levels = levels;
  const Limits limits = levels ? Limits{to_levels(options.fail_threshold), to_levels(options.hard_fail_threshold)}
                               : Limits{options.fail_threshold, options.hard_fail_threshold};
  double sum = 0.0;
  double d[kMaxChannels];
  for (size_t p = 0; p < pixel_count; ++p) {
    double worst = 0.0;  // in levels or on [0,1], as `limits`
    for (int c = 0; c < channels; ++c) {
      const size_t i = p * channels + c;
      const double diff = levels ? std::abs(level(a.pixels[i]) - level(b.pixels[i]))
                                 : channel_diff(a.pixels[i], b.pixels[i]);
      worst = std::max(worst, diff);
      d[c] = levels ? diff / 255.0 : diff;
      sum += d[c];
    }
    result.max_abs = std::max(result.max_abs, levels ? worst / 255.0 : worst);
    if (levels) result.max_levels = std::max(result.max_levels, static_cast<int>(worst));
    if (worst > limits.fail) ++result.failing_pixels;
    if (worst > limits.hard_fail) ++result.hard_failing_pixels;
    write_diff_pixel(d, channels, &result.diff.pixels[p * channels]);
  }
  result.mean_abs = sum / static_cast<double>(a.pixels.size());
  result.failing_percent = 100.0 * static_cast<double>(result.failing_pixels) / static_cast<double>(pixel_count);
  result.passed = result.failing_percent <= options.fail_percent && result.hard_failing_pixels == 0;
  return result;
}

}  // namespace ps
