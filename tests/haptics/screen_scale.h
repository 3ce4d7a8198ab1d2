// Screen scale of a scene's camera, for the hand-speed tests: how many mm of world motion one
// pixel of pointer motion is at a point, computed by projecting with the renderer's own
// view_projection (so it holds for any camera, perspective or orthographic).
#pragma once

#include <glm/glm.hpp>

#include "scene/camera.h"
#include "scene/scene.h"

namespace ps::test {

// mm per pixel for motion along `dir` (unit, world) at world point `p`, at the scene's size.
inline double mm_per_pixel(const Scene& s, const glm::dvec3& p, const glm::dvec3& dir) {
  const double w = s.render.width, h = s.render.height;
  const glm::dmat4 vp = view_projection(s.camera, w / h);
  auto to_px = [&](const glm::dvec3& q) {
    const glm::dvec4 c = vp * glm::dvec4(q, 1.0);
    return glm::dvec2((c.x / c.w + 1.0) * 0.5 * w, (c.y / c.w + 1.0) * 0.5 * h);
  };
  const double step_mm = 1e-3;  // 1 um: the projection's curvature over it is ~1e-5 relative
  return step_mm / glm::length(to_px(p + step_mm * dir) - to_px(p));
}

}  // namespace ps::test
