// The scene's buttons as the window sees them (`pseudoshadow run`): each visible button's face
// projected through the camera the frame drew with, as a window rectangle, and the label drawn
// on it (Button::label, scene-format.md). The layout keeps the readouts and the help off these
// rectangles (app/window/ui_layout.h), so a button is never hidden under text. Pure geometry (no GL, no
// ImGui): unit tested in tests/app/ui_layout_test.cpp.
#pragma once

#include <string>
#include <vector>

#include "app/window/ui_layout.h"
#include "scene/scene.h"

namespace ps {

struct ButtonOverlay {
  UiRect rect;        // the face's bounding box in window pixels, clipped to the window
  std::string label;  // Button::label
  int index = 0;      // into Scene::buttons
};

// Buttons whose face is wholly behind the camera or wholly outside the window are left out.
// `aspect`: the renderer's width / height (the image is stretched to the window).
std::vector<ButtonOverlay> project_buttons(const Scene& scene, const Camera& camera, double aspect, float window_w,
                                           float window_h);

}  // namespace ps
