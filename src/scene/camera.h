// Camera matrices from the scene camera (double precision; the shader gets a float copy).
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace ps {

glm::dmat4 view_projection(const Camera& camera, double aspect);
// Unit vector from the target towards the eye: the initial reference normal ("out of the
// screen", thesis §4.5.2).
glm::dvec3 toward_viewer(const Camera& camera);

}  // namespace ps
