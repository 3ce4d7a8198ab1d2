#include "render/frame_input.h"

namespace ps {

Camera carried_camera(const Camera& camera, const ViewPose& from, const ViewPose& to) {
  if (to == from) return camera;
  const glm::dmat3 turn = to.rotation * glm::transpose(from.rotation);
  auto point = [&](const glm::dvec3& x) { return turn * (x - from.offset_mm) + to.offset_mm; };
  Camera c = camera;
  c.position = point(camera.position);
  c.target = point(camera.target);
  if (to.rotation != from.rotation) c.up = turn * camera.up;
  return c;
}

glm::dvec3 carried_direction(const glm::dvec3& direction, const ViewPose& from, const ViewPose& to) {
  if (to.rotation == from.rotation) return direction;
  return to.rotation * glm::transpose(from.rotation) * direction;
}

Camera unposed_camera(const Camera& world, const ViewPose& pose) {
  const glm::dmat3 back = glm::transpose(pose.rotation);
  Camera c = world;
  c.position = back * (world.position - pose.offset_mm);
  c.target = back * (world.target - pose.offset_mm);
  c.up = back * world.up;
  return c;
}

FrameInput probe_frame_input(const glm::dvec3& position_mm, const glm::dvec3& velocity_mm_s) {
  FrameInput in;
  in.probe = ProbeMotion{position_mm, velocity_mm_s};
  return in;
}

FrameInput start_frame_input(const Scene& scene) {
  FrameInput in;
  in.bodies_mm = start_positions(scene);
  in.markers = world_markers(scene, scene.probe.position, *in.bodies_mm);
  return in;
}

}  // namespace ps
