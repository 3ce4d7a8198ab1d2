// Invariants of the `normal` AOV (the surface pass's visible normal, which the reference plane
// and the displacement direction are built from), on every covered pixel of scenes seen from
// the front, from behind and from inside:
//   - unit length: the reference-plane mean and the displacement assume it;
//   - facing the viewer (n . view >= 0): a back face's normal is flipped toward the camera, so a
//     surface seen from below pushes the probe toward the viewer, not through the surface.
// Covered pixels come from the CPU ray-cast of the same triangles (tests/support/raycast.h),
// not from the AOV itself, so a pass that writes nothing fails too.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "support/raycast.h"
#include "support/scenes.h"
#include "render/renderer.h"
#include "support/gl_test.h"

namespace ps {
namespace {

struct NormalStats {
  int covered = 0;               // pixels the CPU ray-cast hits
  double max_len_err = 0.0;      // max | |n| - 1 |
  double min_facing = 2.0;       // min n . (toward the camera)
  double mean_facing = 0.0;
};

NormalStats measure_normals(const Scene& s) {
  NormalStats st;
  const auto r = test::render_one_frame(s);
  if (!r) return st;
  const Image nrm = r->read_aov("normal").value();
  const auto meshes = test::scene_meshes(s);
  for (int py = 0; py < s.render.height; ++py)
    for (int px = 0; px < s.render.width; ++px) {
      const test::Ray ray = test::pixel_ray(s, px, py);
      if (!test::raycast(meshes, ray)) continue;
      const glm::dvec3 n(nrm.at(px, py, 0), nrm.at(px, py, 1), nrm.at(px, py, 2));
      const double facing = glm::dot(n, -ray.dir);
      st.max_len_err = std::max(st.max_len_err, std::abs(glm::length(n) - 1.0));
      st.min_facing = std::min(st.min_facing, facing);
      st.mean_facing += facing;
      ++st.covered;
    }
  if (st.covered > 0) st.mean_facing /= st.covered;
  return st;
}

void check_normals(const char* name, const Scene& s, int min_covered) {
  const NormalStats st = measure_normals(s);
  std::printf("[normal] %-14s %5d px  max ||n| - 1| %.2e  min n.view %.4f  mean n.view %.4f\n", name,
              st.covered, st.max_len_err, st.min_facing, st.mean_facing);
  EXPECT_GE(st.covered, min_covered) << name;
  // normalize() in float32: each component rounds to 2^-24 relative, so |n| errs by ~1 ulp
  // (measured <= 1.5e-7 on every scene here). 1e-5 is ~65x that, and far below what a wrong
  // length gives: an unnormalised interpolated normal of the 64-segment sphere is short by up
  // to 2.4e-3 (measured), any other scale (0.5, 2) by far more.
  EXPECT_LT(st.max_len_err, 1e-5) << name;
  // Facing the viewer. The planes' normals are constant, the inside of a sphere is seen along
  // its radii: no grazing interpolated normal, so >= 0 holds without tolerance.
  EXPECT_GE(st.min_facing, 0.0) << name;
}

Scene plane_seen_from(double camera_z) {
  Scene s = test::flat_plane_scene(10.0);
  s.camera.position = {0.0, 0.0, camera_z};
  return s;
}

class NormalAovGLTest : public test::GlTest {};

TEST_P(NormalAovGLTest, PlaneFromAbove) {
  const Scene s = plane_seen_from(100.0);
  check_normals("plane above", s, s.render.width * s.render.height);
}

TEST_P(NormalAovGLTest, PlaneFromBelowIsFlippedTowardTheViewer) {
  Scene s = plane_seen_from(-100.0);  // the plane's back face; the probe stays above it
  check_normals("plane below", s, s.render.width * s.render.height);
}

TEST_P(NormalAovGLTest, TiltedPlaneFromBothSidesInPerspective) {
  for (const double side : {1.0, -1.0}) {
    Scene s = test::flat_plane_scene(10.0);
    s.surfaces[0].rotation_deg = {35.0, -20.0, 0.0};
    s.camera.projection = Projection::kPerspective;
    s.camera.fov_y_deg = 40.0;
    s.camera.position = {20.0 * side, -30.0 * side, 80.0 * side};
    check_normals(side > 0 ? "tilted front" : "tilted back", s, s.render.width * s.render.height / 2);
  }
}

Scene sphere_surface_scene() {
  Scene s = test::flat_plane_scene(0.0);
  Surface& p = s.surfaces[0];
  p.type = SurfaceType::kSphere;
  p.radius_mm = 15.0;
  p.center = {0.0, 0.0, 0.0};
  p.resolution = 64;
  s.probe.position = {0.0, 0.0, 30.0};
  return s;
}

TEST_P(NormalAovGLTest, SphereFromOutsideHasUnitNormals) {
  // Interpolated vertex normals are shorter than 1 between vertices: only normalize() makes
  // them unit. Facing is not checked here: at the silhouette a front-facing facet's
  // interpolated normal may point slightly away from the viewer.
  const Scene s = sphere_surface_scene();
  const NormalStats st = measure_normals(s);
  std::printf("[normal] sphere outside  %5d px  max ||n| - 1| %.2e\n", st.covered, st.max_len_err);
  EXPECT_GT(st.covered, 5000);  // a 30 mm disc in a 40 mm view: ~44 % of 128^2
  EXPECT_LT(st.max_len_err, 1e-5);  // as in check_normals(); measured 1.5e-7
}

TEST_P(NormalAovGLTest, SphereFromInsideIsFlippedTowardTheViewer) {
  Scene s = sphere_surface_scene();
  s.camera.projection = Projection::kPerspective;
  s.camera.fov_y_deg = 60.0;
  s.camera.position = {0.0, 0.0, 0.0};  // at the centre: every pixel sees a back face
  s.camera.target = {0.0, 1.0, 0.0};
  s.camera.up = {0.0, 0.0, 1.0};
  s.probe.position = {0.0, 8.0, 0.0};
  check_normals("sphere inside", s, s.render.width * s.render.height);
}

PS_INSTANTIATE_HEADLESS_BACKENDS(NormalAovGLTest);

}  // namespace
}  // namespace ps
