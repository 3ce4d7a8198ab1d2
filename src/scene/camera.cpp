#include "scene/camera.h"

#include <glm/gtc/matrix_transform.hpp>

namespace ps {

glm::dmat4 view_projection(const Camera& c, double aspect) {
  const glm::dmat4 view = glm::lookAt(c.position, c.target, c.up);
  glm::dmat4 proj;
  if (c.projection == Projection::kOrthographic) {
    const double h = 0.5 * c.ortho_height_mm, w = h * aspect;
    proj = glm::ortho(-w, w, -h, h, c.near_mm, c.far_mm);
  } else {
    proj = glm::perspective(glm::radians(c.fov_y_deg), aspect, c.near_mm, c.far_mm);
  }
  return proj * view;
}

glm::dvec3 toward_viewer(const Camera& c) {
  const glm::dvec3 d = c.position - c.target;
  const double len = glm::length(d);
  return len > 0.0 ? d / len : glm::dvec3(0.0, 0.0, 1.0);
}

}  // namespace ps
