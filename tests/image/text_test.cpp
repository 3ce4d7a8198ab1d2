// The 5x7 label font and contact sheets.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <string>
#include <vector>

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

// A glyph's 5x7 bitmap as drawn at scale 1, one bit per pixel (row-major).
std::uint64_t glyph_bits(char c) {
  Image im = blank(kGlyphWidth, kGlyphHeight);
  draw_text(im, 0, 0, std::string(1, c), {1, 1, 1});
  std::uint64_t bits = 0;
  for (int y = 0; y < kGlyphHeight; ++y)
    for (int x = 0; x < kGlyphWidth; ++x)
      if (im.at(x, y, 0) > 0.5f) bits |= std::uint64_t{1} << (y * kGlyphWidth + x);
  return bits;
}

// Every character that has its own glyph ('?' is the placeholder box itself).
const std::string kGlyphChars =
    "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz .,:-+_=/()%#[]'\"?";

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

TEST(TextTest, LowerCaseHasItsOwnGlyphs) {
  for (char c = 'a'; c <= 'z'; ++c) {
    EXPECT_NE(glyph_bits(c), 0u) << c;
    EXPECT_NE(glyph_bits(c), glyph_bits(static_cast<char>(c - 'a' + 'A'))) << c << " is drawn as upper case";
  }
  Image lower = blank(40, 10), upper = blank(40, 10);
  draw_text(lower, 0, 0, "mm/s", {1, 1, 1});
  draw_text(upper, 0, 0, "MM/S", {1, 1, 1});
  EXPECT_NE(lower.pixels, upper.pixels);
}

TEST(TextTest, AllGlyphsArePairwiseDistinct) {
  for (size_t i = 0; i < kGlyphChars.size(); ++i)
    for (size_t j = i + 1; j < kGlyphChars.size(); ++j)
      EXPECT_NE(glyph_bits(kGlyphChars[i]), glyph_bits(kGlyphChars[j]))
          << "'" << kGlyphChars[i] << "' and '" << kGlyphChars[j] << "' look the same";
}

TEST(TextTest, DescendersStayInsideTheCell) {
  // No row below the baseline: g j p q y reach the bottom row (their tails), and nothing is
  // drawn below row 6 of the cell.
  for (char c : std::string("gjpqy")) {
    Image im = blank(kGlyphWidth, kGlyphHeight + 3);
    draw_text(im, 0, 0, std::string(1, c), {1, 1, 1});
    EXPECT_NE(glyph_bits(c) >> (6 * kGlyphWidth), 0u) << c << " has no tail in the bottom row";
    EXPECT_EQ(lit(im), std::popcount(glyph_bits(c))) << c << " draws below the 7-row cell";
  }
}

TEST(TextTest, UnknownCharactersDrawAsABox) {
  // The hollow 5x7 box: two full rows of 5 and five rows of 2 = 20 pixels.
  for (char c : {'~', '@', '\t', static_cast<char>(0xC3)}) {
    EXPECT_EQ(std::popcount(glyph_bits(c)), 20) << int(c);
    EXPECT_EQ(glyph_bits(c), glyph_bits('?')) << int(c);
  }
}

TEST(TextTest, LabelCharactersAllHaveGlyphs) {
  // What the callers write: sweep labels (last key component=TOML value, scene file stems)
  // and the replay sheet's frame labels.
  const std::string labels = "velocity=[500,0,0] displacement=\"exact_max\" lambda_min=-1.5e-05 table4_1_a "
                             "12 t=0.20 s v=500 mm/s";
  for (char c : labels) EXPECT_NE(glyph_bits(c), glyph_bits('?')) << "'" << c << "' has no glyph";
}

TEST(TextTest, LabelHasTheExpectedPixelWidth) {
  // "t=0.20 s": 8 glyphs; 't' lights its column 0 and 's' its column 4, so the inked span is
  // 7 advances of 6 px plus one 5 px glyph = 47 px at scale 1, 94 px at scale 2.
  Image im = blank(120, 20);
  draw_text(im, 3, 2, "t=0.20 s", {1, 1, 1}, 2);
  int left = im.width, right = -1;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x)
      if (im.at(x, y, 0) > 0.5f) left = std::min(left, x), right = std::max(right, x);
  EXPECT_EQ(left, 3);
  EXPECT_EQ(right - left + 1, 94);
  EXPECT_EQ(text_width("t=0.20 s", 2), 94);
}

TEST(TextTest, ContactSheetLayout) {
  std::vector<Image> ims(5, blank(100, 50));
  const Image sheet = contact_sheet(ims, {"A", "B", "C", "D", "E"}, {.columns = 2, .thumb_width = 50});
  EXPECT_EQ(sheet.width, 4 + 2 * 54);
  EXPECT_EQ(sheet.height, 4 + 3 * (25 + 18 + 4));
  EXPECT_GT(lit(sheet), 0);  // labels drawn in white
}

// A `tune --sweep` label is wider than a 128 px cell (issue: labels ran into each other): it is
// wrapped, every line fits the cell, and nothing is lost (the lines hold every character; spaces
// are compared removed, as a line break replaces one).
TEST(TextTest, WrapTextFitsTheWidthAndKeepsEveryCharacter) {
  const std::string label = "materials.table4_1_a.lambda_min=1.5 mm probe.velocity=[250,0,0] mm/s";
  for (int width : {128, 64, 200, 3}) {
    const auto lines = wrap_text(label, width);
    std::string joined;
    for (const std::string& l : lines) {
      if (l.size() > 1) {  // a single glyph is the least a line holds, whatever the width
        EXPECT_LE(text_width(l), width) << "'" << l << "' at width " << width;
      }
      joined += l;
    }
    std::erase(joined, ' ');
    std::string no_spaces = label;
    std::erase(no_spaces, ' ');
    EXPECT_EQ(joined, no_spaces) << "width " << width;
  }
  // Breaks at spaces first, then after a '.' or '=' (21 glyphs fit in 128 px).
  EXPECT_EQ(wrap_text(label, 128), (std::vector<std::string>{"materials.table4_1_a.", "lambda_min=1.5 mm",
                                                              "probe.velocity=", "[250,0,0] mm/s"}));
  EXPECT_EQ(wrap_text("short", 128), std::vector<std::string>{"short"});
}

// A 3-column sheet of 128^2 cells with sweep labels: no label pixel in the padding between
// cells (a label that ran on would light it), and the label rows grow to hold the lines.
TEST(TextTest, ContactSheetLabelsStayInTheirCells) {
  const std::string label = "materials.table4_1_a.lambda_min=1.5 mm probe.velocity=[250,0,0] mm/s";
  const std::vector<Image> ims(3, blank(128, 128));
  const ContactSheetDesc desc{.columns = 3, .thumb_width = 128, .label_scale = 1};
  const Image sheet = contact_sheet(ims, {label, label, label}, desc);
  EXPECT_EQ(sheet.height, 4 + 128 + 4 * (kGlyphHeight + 2) + 4);
  int in_padding = 0;
  for (int y = 0; y < sheet.height; ++y)
    for (int x = 0; x < sheet.width; ++x) {
      const int in_pitch = (x - desc.padding) % (desc.thumb_width + desc.padding);
      if (x < desc.padding || in_pitch >= desc.thumb_width) in_padding += sheet.at(x, y, 0) > 0.5f;
    }
  EXPECT_EQ(in_padding, 0);
  EXPECT_GT(lit(sheet), 3 * 200);  // the labels are drawn (each of its ~60 glyphs lights ~12 pixels)
}

}  // namespace
}  // namespace ps
