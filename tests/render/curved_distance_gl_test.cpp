// render.shadow_distance = "surface_normal" (issue "What the eye sees", §3): on curved receivers
// the distance d is measured along each surface point's own normal, not along the one reference
// normal. Ground truth per pixel: the CPU ray-cast of the very triangles the GPU draws
// (raycast.h: position and interpolated normal), then that normal's ray against the probe sphere
// in closed form. Receivers: a sphere, a torus and Suzanne, the probe 2 mm above each.
#include <gtest/gtest.h>

#include <cmath>

#include "support/raycast.h"
#include "support/scenes.h"
#include "support/gl_test.h"

namespace ps {
namespace {

class CurvedDistanceGLTest : public test::GlTest {};

Scene receiver_scene(SurfaceType type, const glm::dvec3& look_at, const glm::dvec3& probe, ShadowDistance mode) {
  Scene s = test::flat_plane_scene(probe.z);
  s.probe.position = probe;
  s.camera.position = look_at + glm::dvec3(0.0, 0.0, 100.0);
  s.camera.target = look_at;
  s.camera.ortho_height_mm = 24.0;
  s.render.width = s.render.height = 64;
  s.render.depth_map_size = 256;
  s.render.shadow_distance = mode;
  s.materials[0].textured = false;
  s.materials[0].influence_distance_mm = 12.0;
  Surface& r = s.surfaces[0];
  r.type = type;
  r.resolution = 128;
  if (type == SurfaceType::kSphere) r.radius_mm = 20.0;
  if (type == SurfaceType::kTorus) r.radius_mm = 30.0, r.minor_radius_mm = 10.0;
  if (type == SurfaceType::kMesh) r.mesh_file = "/usr/share/assimp/models/BLEND/Suzanne_248.blend", r.scale = 22.0;
  return s;
}

struct Errors {
  int compared = 0;
  double normal_mode_max = 0.0;   // |d_gpu(surface_normal) - d_exact|, mm
  double thesis_mode_max = 0.0;   // |d_gpu(reference_plane) - d_exact|, mm
  double texel_mm = 0.0;
};

// Both modes against the exact distance along each pixel's own normal, on the pixels whose ray
// meets the probe's underside (the half the depth map holds) away from its silhouette (2 texels:
// there the bilinear depth read mixes in "no probe") and within the influence distance.
Errors measure(SurfaceType type, const glm::dvec3& look_at, const glm::dvec3& probe) {
  Errors e;
  Scene normal_scene = receiver_scene(type, look_at, probe, ShadowDistance::kSurfaceNormal);
  Scene thesis_scene = receiver_scene(type, look_at, probe, ShadowDistance::kReferencePlane);
  auto by_normal = test::render_one_frame(normal_scene);
  auto by_plane = test::render_one_frame(thesis_scene);
  if (!by_normal || !by_plane) return e;
  const Image dn = by_normal->read_aov("distance").value(), dp = by_plane->read_aov("distance").value();
  const glm::dvec3 ref = by_normal->reference().n;
  const int n = normal_scene.render.depth_map_size;
  const double r = normal_scene.probe.radius_mm;
  e.texel_mm = 2.0 * r * (1.0 + 2.0 / n) / n;
  const std::vector<Mesh> meshes = test::scene_meshes(normal_scene);
  for (int py = 0; py < normal_scene.render.height; ++py)
    for (int px = 0; px < normal_scene.render.width; ++px) {
      const auto hit = test::raycast(meshes, test::pixel_ray(normal_scene, px, py));
      if (!hit) continue;
      const glm::dvec3 pc = hit->position - probe, nn = hit->normal;
      const double b = glm::dot(nn, pc), cc = glm::dot(pc, pc) - r * r, disc = b * b - cc;
      if (cc <= 0.0 || disc < 0.0) continue;
      const double s = -b - std::sqrt(disc);
      if (s < 0.0 || s > 11.0) continue;
      const glm::dvec3 q = hit->position + s * nn - probe;
      const double across = glm::length(q - glm::dot(q, ref) * ref);
      if (glm::dot(q, ref) > 0.0 || across > r - 2.0 * e.texel_mm) continue;
      ++e.compared;
      e.normal_mode_max = std::max(e.normal_mode_max, std::abs(dn.at(px, py, 0) - s));
      if (!std::isnan(dp.at(px, py, 0))) e.thesis_mode_max = std::max(e.thesis_mode_max, std::abs(dp.at(px, py, 0) - s));
    }
  return e;
}

// Within half a depth-map texel (0.032 mm here) on every receiver, where the reference-plane
// distance is off by millimetres on the sphere and the torus (the thesis's single plane).
TEST_P(CurvedDistanceGLTest, SurfaceNormalModeMeetsTheExactDistanceOnCurvedReceivers) {
  struct Case {
    const char* name;
    SurfaceType type;
    glm::dvec3 look_at, probe;
  };
  for (const Case& c : {Case{"sphere", SurfaceType::kSphere, {0, 0, 0}, {0, 0, 30}},
                        Case{"torus", SurfaceType::kTorus, {30, 0, 0}, {30, 0, 20}},
                        Case{"suzanne", SurfaceType::kMesh, {0, 0, 0}, {0, 0, 25}}}) {
    const Errors e = measure(c.type, c.look_at, c.probe);
    EXPECT_GT(e.compared, 150) << c.name;
    EXPECT_LE(e.normal_mode_max, 0.5 * e.texel_mm) << c.name << ": texel " << e.texel_mm << " mm";
    RecordProperty(std::string(c.name) + "_normal_mode_max_mm", std::to_string(e.normal_mode_max));
    RecordProperty(std::string(c.name) + "_thesis_mode_max_mm", std::to_string(e.thesis_mode_max));
    RecordProperty(std::string(c.name) + "_pixels", std::to_string(e.compared));
    if (c.type != SurfaceType::kMesh) {
      EXPECT_GT(e.thesis_mode_max, 0.5) << c.name;
    }
  }
}

// On a plane facing the probe the surface's normal is the reference normal: the same image and
// the same distances as the thesis's mode, bit for bit.
TEST_P(CurvedDistanceGLTest, OnAPlaneBothModesAgreeBitForBit) {
  Scene a = test::flat_plane_scene(10.0), b = a;
  b.render.shadow_distance = ShadowDistance::kSurfaceNormal;
  auto ra = test::render_one_frame(a), rb = test::render_one_frame(b);
  ASSERT_TRUE(ra && rb);
  EXPECT_TRUE(ra->read_color().pixels == rb->read_color().pixels);
  const Image da = ra->read_aov("distance").value(), db = rb->read_aov("distance").value();
  ASSERT_EQ(da.pixels.size(), db.pixels.size());
  int differ = 0, shadowed = 0;  // NaN (no probe above) in both counts as equal
  for (std::size_t i = 0; i < da.pixels.size(); ++i) {
    const float x = da.pixels[i], y = db.pixels[i];
    shadowed += !std::isnan(x);
    differ += !(x == y || (std::isnan(x) && std::isnan(y)));
  }
  EXPECT_GT(shadowed, 100);
  EXPECT_EQ(differ, 0);
}

PS_INSTANTIATE_HEADLESS_BACKENDS(CurvedDistanceGLTest);

}  // namespace
}  // namespace ps
