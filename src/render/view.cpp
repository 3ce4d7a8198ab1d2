#include "render/view.h"

namespace ps {

Result<std::shared_ptr<View>> make_view(const Scene& scene, ViewFlags show) {
  auto deformables = world::settled_deformables(scene);
  if (!deformables) return deformables.error();
  auto view = std::make_shared<View>();
  view->probe = scene.probe;
  view->camera = scene.camera;
  view->light = scene.light;
  view->show = show;
  view->deformables = std::move(deformables.value());
  apply_input(*view, start_frame_input(scene));
  return view;
}

void apply_input(View& view, const FrameInput& in) {
  if (in.probe) {
    view.probe.position = in.probe->position_mm;
    view.probe.velocity = in.probe->velocity_mm_s;
  }
  if (in.camera) view.camera = *in.camera;
  if (in.view) {
    view.camera = carried_camera(view.camera, view.pose, *in.view);
    view.light.direction = carried_direction(view.light.direction, view.pose, *in.view);
    view.pose = *in.view;
  }
  if (in.device_mm) view.device_mm = *in.device_mm;
  if (in.sheet) view.sheet = *in.sheet;
  if (in.bodies_mm) view.bodies_mm = *in.bodies_mm;
  if (in.markers) view.markers = *in.markers;
  if (in.show) view.show = *in.show;
}

Result<std::shared_ptr<View>> rebuilt_view(const View& now, const Scene& scene, ViewRestart restart) {
  auto next = make_view(scene, now.show);
  if (!next) return next;
  View& v = *next.value();
  if (!restart.camera) v.camera = now.workspace_camera();
  if (!restart.probe) {
    v.probe.position = now.probe.position;
    v.probe.velocity = now.probe.velocity;
  }
  return next;
}

}  // namespace ps
