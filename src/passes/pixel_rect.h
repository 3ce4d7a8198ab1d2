// A rectangle of pixels in GL window coordinates (origin at the bottom-left pixel, as
// glScissor takes it), half-open: x0 <= x < x1, y0 <= y < y1.
#pragma once

#include <algorithm>

namespace ps {

struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;

  static PixelRect whole(int width, int height) { return {0, 0, width, height}; }
  bool empty() const { return x1 <= x0 || y1 <= y0; }
  int width() const { return empty() ? 0 : x1 - x0; }
  int height() const { return empty() ? 0 : y1 - y0; }
  bool contains(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
  // The part inside `other` (empty rectangles come out as {0, 0, 0, 0}).
  PixelRect clipped_to(const PixelRect& other) const {
    const PixelRect r{std::max(x0, other.x0), std::max(y0, other.y0), std::min(x1, other.x1),
                      std::min(y1, other.y1)};
    return r.empty() ? PixelRect{} : r;
  }
  bool operator==(const PixelRect&) const = default;
};

}  // namespace ps
