// The 5x7 label font and contact sheets.
#include <gtest/gtest.h>

#include "image/text.h"

namespace ps {
namespace {

Image blank(int w, int h) {
  Image im;
  im.width = w;
  im.height = h;
  im.channels = 3;
  im.pixels.assign(static_cast<size_t>(w) * h * 3, 0.0f);
  return im;
}

int lit(const Image& im) {
  int n = 0;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) n += im.at(x, y, 0) > 0.5f;
  return n;
}

TEST(TextTest, GlyphsHaveTheirPixelCount) {
  Image im = blank(40, 10);
  draw_text(im, 0, 0, "1", {1, 1, 1});
  EXPECT_EQ(lit(im), 10);  // '1': 1+2+1+1+1+1+3 pixels per row
}

TEST(TextTest, ScaleMultipliesAreaAndClipsAtEdges) {
  Image a = blank(64, 16), b = blank(128, 32);
  draw_text(a, 0, 0, "T", {1, 1, 1}, 1);
  draw_text(b, 0, 0, "T", {1, 1, 1}, 2);
  EXPECT_EQ(lit(b), 4 * lit(a));
  Image c = blank(8, 8);
  draw_text(c, -3, -3, "HELLO", {1, 1, 1}, 3);  // partly outside: must not crash
  EXPECT_GT(lit(c), 0);
  EXPECT_EQ(text_width("AB", 2), 22);
}

TEST(TextTest, ContactSheetLayout) {
  std::vector<Image> ims(5, blank(100, 50));
  const Image sheet = contact_sheet(ims, {"A", "B", "C", "D", "E"}, {.columns = 2, .thumb_width = 50});
  EXPECT_EQ(sheet.width, 4 + 2 * 54);
  EXPECT_EQ(sheet.height, 4 + 3 * (25 + 18 + 4));
  EXPECT_GT(lit(sheet), 0);  // labels drawn in white
}

}  // namespace
}  // namespace ps
