// Labels drawn into images with a tiny built-in 5x7 bitmap font (ASCII: digits, upper and
// lower case letters - so units read as written, mm and s - and common punctuation; any other
// character draws as a hollow box), and labelled contact sheets made of several images.
// Lower-case descenders (g j p q y) stay inside the 7-row cell: those glyphs sit one row higher.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "image/image.h"

namespace ps {

constexpr int kGlyphWidth = 5, kGlyphHeight = 7, kGlyphAdvance = 6;  // pixels at scale 1

// Draws `text` with its top-left corner at (x, y) (row 0 = top); each font pixel becomes a
// scale x scale block; pixels outside the image are skipped. Channels beyond RGB are untouched.
void draw_text(Image& image, int x, int y, const std::string& text, const glm::vec3& color, int scale = 1);
int text_width(const std::string& text, int scale = 1);
// `text` broken into lines no wider than `max_width` pixels (text_width): at spaces first; a word
// too long for a line breaks after its last '.', '=', ',' or '_' that fits ('.' and '=' first),
// else between two characters. At least one character per line, so a very narrow width still
// terminates.
std::vector<std::string> wrap_text(const std::string& text, int max_width, int scale = 1);

struct ContactSheetDesc {
  int columns = 4;
  int thumb_width = 256;   // images are scaled (nearest) to this width, aspect kept
  int padding = 4;         // pixels between cells and around the sheet
  int label_scale = 2;
  glm::vec3 background{0.1f, 0.1f, 0.1f};
  glm::vec3 label_color{1.0f, 1.0f, 1.0f};
};

// One RGB image: thumbnails in rows, each with its label underneath, wrapped to the cell's
// width (wrap_text) so labels never run into the next cell; every label row is as tall as its
// longest label. Images must be RGB or RGBA; labels.size() must equal images.size().
Image contact_sheet(const std::vector<Image>& images, const std::vector<std::string>& labels,
                    const ContactSheetDesc& desc = {});

}  // namespace ps
