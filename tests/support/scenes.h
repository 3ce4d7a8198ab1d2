// Scenes built in code for the analytic GL tests (no scene file involved).
#pragma once

#include <memory>

#include <glm/glm.hpp>

#include "render/renderer.h"
#include "scene/scene.h"

namespace ps::test {

// A 200 x 200 mm plane at z = 0 (normal +Z), one material, sphere probe of radius 8 mm at
// (0, 0, probe_z); orthographic camera looking straight down on a 40 x 40 mm view, 128^2.
Scene flat_plane_scene(double probe_z);

// World (x, y) of the centre of pixel (px, py) (row 0 = top) for flat_plane_scene's camera.
glm::dvec2 pixel_to_world(const Scene& scene, int px, int py);

// A renderer of `s` that has drawn one frame; null (with a test failure naming why) when it
// cannot be created or the frame fails. Needs a current GL context.
std::unique_ptr<Renderer> render_one_frame(const Scene& s);

}  // namespace ps::test
