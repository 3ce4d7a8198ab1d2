#include "app/window/button_overlay.h"

#include <algorithm>

#include "scene/camera.h"
#include "scene/mesh.h"

namespace ps {

std::vector<ButtonOverlay> project_buttons(const Scene& scene, const Camera& camera, double aspect, float window_w,
                                           float window_h) {
  std::vector<ButtonOverlay> out;
  const glm::dmat4 vp = view_projection(camera, aspect);
  for (std::size_t i = 0; i < scene.buttons.size(); ++i) {
    const Button& b = scene.buttons[i];
    if (!b.visible) continue;
    const glm::dmat3 rot = euler_xyz_deg(b.rotation_deg);  // local +Z is the face's normal
    const glm::dvec2 half = 0.5 * b.size_mm;
    UiRect r{1e30f, 1e30f, -1e30f, -1e30f};
    bool behind = false;
    for (const glm::dvec2 corner : {glm::dvec2(-1, -1), glm::dvec2(1, -1), glm::dvec2(1, 1), glm::dvec2(-1, 1)}) {
      const glm::dvec3 p = b.center + rot * glm::dvec3(corner * half, 0.0);
      const glm::dvec4 clip = vp * glm::dvec4(p, 1.0);
      if (!(clip.w > 0.0)) behind = true;  // a corner behind the eye has no place on screen
      const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
      const float x = static_cast<float>((ndc.x + 1.0) * 0.5 * window_w);
      const float y = static_cast<float>((1.0 - ndc.y) * 0.5 * window_h);
      r = {std::min(r.x0, x), std::min(r.y0, y), std::max(r.x1, x), std::max(r.y1, y)};
    }
    if (behind) continue;
    r = {std::max(r.x0, 0.f), std::max(r.y0, 0.f), std::min(r.x1, window_w), std::min(r.y1, window_h)};
    if (r.empty()) continue;  // outside the window
    out.push_back({r, b.label, static_cast<int>(i)});
  }
  return out;
}

}  // namespace ps
