// The rolling manifold through `replay`'s own session code (replay_session), on both headless
// backends: the frames show the view turned with the haptics (docs/fourd.md, "Rolling
// manifold"). A hand pressed into the flat torus at the screen centre walks sideways in its
// workspace (without rolling: along the curved surface, 1 mm in); with fourd_roll the
// touched facet faces the viewer in the picture, without it the torus there is seen obliquely; either way the pseudo-shadow sits where the haptic proxy
// projects through the camera the frame was drawn with (graphics and haptics together).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "app/session/session.h"
#include "devices/pointer_map.h"
#include "devices/sample_log.h"
#include "scene/scene_io.h"
#include "support/gl_test.h"
#include "world/haptic_scene.h"

namespace ps {
namespace {

class RollingGLTest : public test::GlTest {};

struct WalkFrame {
  bool have = false;
  double centroid_px_x = 0.0, centroid_px_y = 0.0;  // the shadow's (intensity >= 0.5)
  double proxy_px_x = 0.0, proxy_px_y = 0.0;         // the proxy projected through the frame's camera
  double normal_angle = 0.0;  // picture's normal at the shadow's centre vs the camera's axis, rad
  int shadow_pixels = 0;
  double view_turn = 0.0;     // the view's turn, rad
};

// With rolling: the shipped scene and its walk (scenes/fourd/flat_torus_rolling.toml,
// tests/fourd/data/flat_torus_roll.traj). Without: the same scene with fourd_roll = false and the
// hand following the curved surface, 1 mm in. The frame at t = 2 s: the hand 17 mm aside.
WalkFrame walk(bool roll) {
  const std::string file = std::string(PS_SOURCE_DIR) + "/scenes/fourd/flat_torus_rolling.toml";
  auto scene = load_scene(file, {std::string("surfaces.0.fourd_roll=") + (roll ? "true" : "false"),
                                 "render.size=[256,256]"});
  EXPECT_TRUE(scene) << scene.error().message;
  auto hs = world::HapticScene::build(scene.value());
  EXPECT_TRUE(hs) << hs.error().message;
  auto renderer = Renderer::create(scene.value(), RendererOptions{});
  EXPECT_TRUE(renderer) << renderer.error().message;
  const double r = scene.value().probe.radius_mm;
  auto log = load_sample_log(std::string(PS_SOURCE_DIR) + "/tests/fourd/data/flat_torus_roll.traj");
  EXPECT_TRUE(log) << log.error().message;
  std::vector<DeviceSample> samples = log.value();
  if (!roll)
    for (std::size_t i = 1; i < samples.size(); ++i) {
      const world::Contact c = hs.value().closest(samples[i].position_mm, 30.0);
      EXPECT_TRUE(c.hit);
      samples[i].position_mm = c.point + (r - 1.0) * glm::normalize(samples[i].position_mm - c.point);
    }
  LogDevice device(samples, true, "walk");
  ReplayOptions opt;
  opt.fps = 10.0;
  opt.haptic_scene = &hs.value();
  WalkFrame out;
  auto sink = [&](int, double t, const HapticState& st, const Renderer& rr) -> Status {
    if (std::abs(t - 2.0) > 1e-6) return ok_status();
    auto intensity = rr.read_aov(Aov::kIntensity);
    auto normal = rr.read_aov(Aov::kNormal);
    if (!intensity || !normal) return make_error("read_aov failed");
    const Image& in = intensity.value();
    double sx = 0.0, sy = 0.0;
    for (int y = 0; y < in.height; ++y)
      for (int x = 0; x < in.width; ++x)
        if (in.at(x, y, 0) >= 0.5) {
          sx += x + 0.5;
          sy += y + 0.5;
          ++out.shadow_pixels;
        }
    if (out.shadow_pixels == 0) return ok_status();
    out.have = true;
    out.centroid_px_x = sx / out.shadow_pixels;
    out.centroid_px_y = sy / out.shadow_pixels;
    const Camera& cam = rr.camera();  // the world camera this frame drew with
    PointerView v;
    v.camera = cam;
    v.window_size = {static_cast<double>(in.width), static_cast<double>(in.height)};
    // The shadow is the probe projected along the reference normal: its centre is the proxy's
    // contact point, the proxy moved back by r along the facet's normal.
    const glm::dvec3 axis = glm::normalize(cam.position - cam.target);
    const glm::dvec2 p = project_to_window(v, st.proxy_mm - r * axis);
    out.proxy_px_x = p.x;
    out.proxy_px_y = p.y;
    const int cx = static_cast<int>(out.centroid_px_x), cy = static_cast<int>(out.centroid_px_y);
    const glm::dvec3 n(normal.value().at(cx, cy, 0), normal.value().at(cx, cy, 1), normal.value().at(cx, cy, 2));
    out.normal_angle = std::acos(std::min(1.0, std::abs(glm::dot(glm::normalize(n), axis))));
    out.view_turn = std::acos(std::clamp(0.5 * (st.view_rotation[0][0] + st.view_rotation[1][1] + st.view_rotation[2][2] - 1.0), -1.0, 1.0));
    return ok_status();
  };
  auto res = replay_session(*renderer.value(), device, opt, sink);
  EXPECT_TRUE(res) << res.error().message;
  return out;
}

// Rolling: the picture's normal under the shadow is within 0.2 rad of the camera's axis (the
// facet faces the viewer exactly, fourd_haptic_test; the picture shades with interpolated vertex
// normals, which lean from the facet's by up to half the angle between neighbouring facets,
// ~0.15 rad on the 900-polygon torus, plus the 80 ms turn's lag). Without rolling the torus
// 17 mm aside is seen obliquely: more than 0.25 rad (measured 0.10 rolling, 0.33 fixed). Both: the shadow's centroid is
// within 3 px of the proxy's contact point projected through the frame's camera (at 256^2 the
// probe's 3 mm radius covers ~5 px; the shadow is the probe's projection along the reference
// normal, which leans a little from the facet's).
TEST_P(RollingGLTest, TheTouchedFacetFacesTheViewerInThePicture) {
  const WalkFrame on = walk(true), off = walk(false);
  std::printf("rolling: %d shadow px at (%.1f, %.1f), proxy at (%.1f, %.1f), normal %.3f rad off the axis, view "
              "turned %.3f rad\n",
              on.shadow_pixels, on.centroid_px_x, on.centroid_px_y, on.proxy_px_x, on.proxy_px_y, on.normal_angle,
              on.view_turn);
  std::printf("fixed: %d shadow px at (%.1f, %.1f), proxy at (%.1f, %.1f), normal %.3f rad off the axis\n",
              off.shadow_pixels, off.centroid_px_x, off.centroid_px_y, off.proxy_px_x, off.proxy_px_y, off.normal_angle);
  ASSERT_TRUE(on.have);
  ASSERT_TRUE(off.have);
  EXPECT_GT(on.view_turn, 0.1) << "the view rolled";
  EXPECT_LT(on.normal_angle, 0.2);
  EXPECT_GT(off.normal_angle, 0.25);
  for (const WalkFrame* f : {&on, &off}) {
    EXPECT_LT(std::hypot(f->centroid_px_x - f->proxy_px_x, f->centroid_px_y - f->proxy_px_y), 3.0);
  }
}

PS_INSTANTIATE_HEADLESS_BACKENDS(RollingGLTest);

}  // namespace
}  // namespace ps
