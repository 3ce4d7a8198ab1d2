#include "support/scenes.h"

#include <gtest/gtest.h>

namespace ps::test {

Scene flat_plane_scene(double probe_z) {
  Scene s;
  s.path = "<test>";
  s.camera.projection = Projection::kOrthographic;
  s.camera.position = {0.0, 0.0, 100.0};
  s.camera.target = {0.0, 0.0, 0.0};
  s.camera.up = {0.0, 1.0, 0.0};
  s.camera.ortho_height_mm = 40.0;
  s.camera.near_mm = 1.0;
  s.camera.far_mm = 1000.0;
  s.render.width = s.render.height = 128;
  Material m;
  m.name = "plain";
  m.albedo = {0.8, 0.8, 0.8};
  s.materials.push_back(m);
  Surface p;
  p.type = SurfaceType::kPlane;
  p.material = "plain";
  p.material_index = 0;
  p.size_mm = {200.0, 200.0};
  p.resolution = 4;
  s.surfaces.push_back(p);
  s.probe.shape = ProbeShape::kSphere;
  s.probe.radius_mm = 8.0;
  s.probe.position = {0.0, 0.0, probe_z};
  return s;
}

glm::dvec2 pixel_to_world(const Scene& s, int px, int py) {
  const double h = s.camera.ortho_height_mm;
  const double w = h * s.render.width / s.render.height;
  const double x = (px + 0.5) / s.render.width * w - 0.5 * w;
  const double y = 0.5 * h - (py + 0.5) / s.render.height * h;
  return {x, y};
}

std::unique_ptr<Renderer> render_one_frame(const Scene& s) {
  auto r = Renderer::create(s, {});
  if (!r.ok()) {
    ADD_FAILURE() << r.error().message;
    return nullptr;
  }
  if (Status frame = r.value()->render_frame(); !frame) {
    ADD_FAILURE() << frame.error().message;
    return nullptr;
  }
  return std::move(r.value());
}

}  // namespace ps::test
