#include "maze/maze_screen.h"

#include <algorithm>
#include <cstdio>

#include "image/text.h"

namespace ps::maze {

glm::ivec2 stamp_label(Image& im, const std::string& label) {
  if (label.empty()) return {0, 0};
  // The label grows with the image (2x at 512 px) so it reads the same in a window or a frame.
  const int scale = std::max(1, im.width / 256), w = std::min(im.width, text_width(label, scale) + 8 * scale),
            h = std::min(im.height, 11 * scale);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) im.at(x, y, c) = 0.05f;
  draw_text(im, 4 * scale, 2 * scale, label, {1.0f, 0.95f, 0.5f}, scale);
  return {w, h};
}

Image score_image(const PassScore& s, bool cues) {
  Image im;
  im.width = 512;
  im.height = 72 + 28 * static_cast<int>(s.trials.size());
  im.channels = 3;
  im.pixels.assign(static_cast<std::size_t>(im.width) * im.height * 3, 0.08f);
  char line[128];
  std::snprintf(line, sizeof line, "pass %d: %d of %zu rooms right", s.pass + 1, s.correct(), s.trials.size());
  draw_text(im, 16, 16, line, {1.0f, 1.0f, 1.0f}, 3);
  int y = 60;
  for (const Trial& t : s.trials) {
    std::snprintf(line, sizeof line, "room %d %-14s %-8s %s", t.index + 1, cues ? "" : cue_label(t.cue),
                  exit_name(t.chosen), t.ok ? "RIGHT" : "WRONG");
    draw_text(im, 16, y, line, t.ok ? glm::vec3(0.4f, 1.0f, 0.4f) : glm::vec3(1.0f, 0.4f, 0.35f), 2);
    y += 28;
  }
  return im;
}

}  // namespace ps::maze
