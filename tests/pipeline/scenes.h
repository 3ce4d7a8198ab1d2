// Scenes built in code for the analytic GL tests (no scene file involved).
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace ps::test {

// A 200 x 200 mm plane at z = 0 (normal +Z), one material, sphere probe of radius 8 mm at
// (0, 0, probe_z); orthographic camera looking straight down on a 40 x 40 mm view, 128^2.
Scene flat_plane_scene(double probe_z);

// World (x, y) of the centre of pixel (px, py) (row 0 = top) for flat_plane_scene's camera.
glm::dvec2 pixel_to_world(const Scene& scene, int px, int py);

}  // namespace ps::test
