// The step from the haptic loop's state to a frame (frame/haptic_frame.h): what haptic_frame_input
// takes from the state, checked field by field against the state it was given, on a scene with
// none of the world's extras (the default) and on one with bodies and charges
// (fields_bodies_demo). One backend: no pixel is compared, only the input built for the frame.
#include <gtest/gtest.h>

#include <string>

#include "frame/haptic_frame.h"
#include "render/renderer.h"
#include "scene/scene_io.h"
#include "support/gl_test.h"

namespace ps {
namespace {

class HapticFrameGLTest : public test::GlTest {};

std::unique_ptr<Renderer> open(const std::string& path) {
  auto scene = path.empty() ? parse_scene(default_scene_text(), "<default>", default_scene_base_dir(), {"render.size=[64,64]"})
                            : load_scene(std::string(PS_SOURCE_DIR) + "/" + path, {"render.size=[64,64]"});
  EXPECT_TRUE(scene.ok()) << scene.error().message;
  auto r = Renderer::create(scene.value(), {});
  EXPECT_TRUE(r.ok()) << r.error().message;
  return std::move(r.value());
}

// Before the device's first sample the frame moves nothing of the probe: no probe, no hand (the
// view keeps the scene's probe where it starts).
TEST_P(HapticFrameGLTest, WithoutASampleTheViewKeepsItsProbe) {
  auto r = open("");
  const FrameInput in = haptic_frame_input(*r, HapticState{}, {});
  EXPECT_FALSE(in.probe.has_value());
  EXPECT_FALSE(in.device_mm.has_value());
  EXPECT_EQ(drawn_probe(*r, in), r->probe().position);
}

// On a plain scene (no stretch, no deformable surface) the probe is drawn where the proxy is, at
// the filter's velocity, the hand where the device is, in the state's view pose; no bodies, no
// markers. Exact: nothing is computed on the way.
TEST_P(HapticFrameGLTest, OnAPlainSceneTheProbeIsTheProxy) {
  auto r = open("");
  HapticState st;
  st.have_sample = true;
  st.proxy_mm = {3.0, -4.0, 5.5};
  st.position_mm = {3.0, -4.0, 2.0};
  st.velocity_mm_s = {12.0, 0.5, 0.0};
  st.device_mm = {3.0, -4.0, 1.0};
  st.view_offset_mm = {0.0, 7.0, 0.0};
  const FrameInput in = haptic_frame_input(*r, st, {});
  ASSERT_TRUE(in.probe.has_value());
  EXPECT_EQ(in.probe->position_mm, st.proxy_mm);
  EXPECT_EQ(in.probe->velocity_mm_s, st.velocity_mm_s);
  ASSERT_TRUE(in.device_mm.has_value());
  EXPECT_EQ(*in.device_mm, st.device_mm);
  ASSERT_TRUE(in.view.has_value());
  EXPECT_EQ(in.view->offset_mm, st.view_offset_mm);
  ASSERT_TRUE(in.bodies_mm.has_value());
  EXPECT_TRUE(in.bodies_mm->empty());
  ASSERT_TRUE(in.markers.has_value());
  EXPECT_TRUE(in.markers->empty()) << "no charges, bands or fields on the default scene";
  EXPECT_EQ(drawn_probe(*r, in), st.proxy_mm);
}

// The bodies are the state's, in order and no more than it holds; a live charge adds a marker.
TEST_P(HapticFrameGLTest, BodiesAndLiveChargesComeFromTheState) {
  auto r = open("scenes/fields_bodies_demo.toml");
  ASSERT_FALSE(r->scene().bodies.empty());
  HapticState st;
  st.have_sample = true;
  st.proxy_mm = {0.0, 0.0, 30.0};
  st.body_count = 1;
  st.body_mm[0] = {11.0, -2.0, 40.0};
  st.body_mm[1] = {99.0, 99.0, 99.0};  // beyond body_count: not a body
  const FrameInput without = haptic_frame_input(*r, st, {});
  ASSERT_TRUE(without.bodies_mm.has_value());
  ASSERT_EQ(without.bodies_mm->size(), 1u);
  EXPECT_EQ((*without.bodies_mm)[0], st.body_mm[0]);
  HapticFrameSources sources;
  sources.charges.count = 1;
  sources.charges.position[0] = {-20.0, 10.0, 5.0};
  sources.charges.charge_n_mm2[0] = 50.0;
  const FrameInput with = haptic_frame_input(*r, st, sources);
  ASSERT_TRUE(with.markers.has_value() && without.markers.has_value());
  EXPECT_EQ(with.markers->size(), without.markers->size() + 1) << "one marker for the live charge";
}

INSTANTIATE_TEST_SUITE_P(Headless, HapticFrameGLTest, ::testing::Values(::ps::gl::Backend::kEgl),
                         ::ps::test::backend_param_name);

}  // namespace
}  // namespace ps
