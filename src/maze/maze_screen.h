// What the maze puts on screen besides the scene, as pictures: the room label in a frame's top
// left corner (cues off only: Sepulveda-Cervantes et al. §VI item 2) and the score screen
// after a pass (§VI item 3). The headless session writes them; tests read them. No GL
// (image/text.h's bitmap font).
#pragma once

#include <string>

#include "image/image.h"
#include "maze/maze_track.h"

namespace ps::maze {

// Draws `label` on a dark box in the top left corner; nothing for an empty label (cues on).
// Returns the box's width and height in pixels (0, 0 when nothing was drawn).
glm::ivec2 stamp_label(Image& frame, const std::string& label);

// Per room of the pass: its place, its label (cues off only), the exit taken, RIGHT or WRONG.
Image score_image(const PassScore& score, bool cues);

}  // namespace ps::maze
