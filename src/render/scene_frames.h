// A scene's frames as `pseudoshadow render` draws them, for every caller that renders a scene
// without a haptic loop (the CLI's render, tune's sweeps, the C++ API and so the Python module):
// the renderer's view as it stands, a fresh view showing the world where the scene starts it
// (bodies, charges, bands: render/view.h make_view), held while the probe moves by each frame's
// displacement. One function, so the library's first image is the CLI's byte for byte (tests/api).
#pragma once

#include <functional>

#include "core/result.h"
#include "render/renderer.h"

namespace ps {

// `frames` frames of `renderer`'s scene; `after_frame(i)` (optional) is called after frame i
// (0-based): the CLI's progress line.
Status render_scene_frames(Renderer& renderer, int frames, const std::function<void(int)>& after_frame = {});

}  // namespace ps
