// The maze's pictures (needs GL; EGL and OSMesa): the room label shows only with cues off; the
// hidden sphere draws no pixel; the texture room's pseudo-shadow is textured where the dummy
// room's is plain, and with cues off the two rooms look alike; a session's frames through run's
// frame path (haptic_frame_input) are the probe's and the follow camera's alone. Frames as
// `maze --every` draws them: the generated scene, the camera following the probe.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "devices/sample_log.h"
#include "frame/haptic_frame.h"
#include "maze/maze.h"
#include "maze/maze_frames.h"
#include "maze/maze_screen.h"
#include "maze/maze_script.h"
#include "maze_test_util.h"
#include "render/renderer.h"
#include "support/gl_test.h"

namespace ps::maze {
namespace {

class MazeGLTest : public ps::test::GlTest {};

struct Shot {
  MazeDesc desc;
  Route route = draw_route(3);
  glm::dvec3 room(Cue cue) const {
    const RoomGeometry g = room_geometry(desc);
    const auto order = route.order(0);
    for (int i = 0; i < kRoomsPerPass; ++i)
      if (order[static_cast<std::size_t>(i)] == cue) return {0.0, g.center_y(i), 0.0};
    return glm::dvec3(NAN);
  }
};

Shot shot(int size) {
  Shot s;
  auto d = load_maze_desc(test::maze_file());
  EXPECT_TRUE(d) << d.error().message;
  s.desc = d.value();
  s.desc.image_size = size;
  return s;
}

Image render(const Shot& s, const Scene& scene, const glm::dvec3& probe, const glm::dvec3& velocity) {
  auto r = Renderer::create(scene, RendererOptions{});
  EXPECT_TRUE(r) << r.error().message;
  if (!r) return {};
  FrameInput in = probe_frame_input(probe, velocity);
  in.camera = follow_camera(s.desc, probe);
  EXPECT_TRUE(r.value()->render(in));
  return r.value()->read_color();
}

Scene scene_of(const Shot& s, bool cues) {
  auto m = generate_scene(s.desc, s.route, cues, 0);
  EXPECT_TRUE(m) << m.error().message;
  return m->scene;
}

int differing(const Image& a, const Image& b, int x0, int y0, int x1, int y1) {
  int n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      for (int c = 0; c < 3; ++c)
        if (a.at(x, y, c) != b.at(x, y, c)) {
          ++n;
          break;
        }
  return n;
}

// At the start (the dummy room ahead, which has no cue) both conditions draw the same frame,
// byte for byte; the label makes the only difference, inside its box, and only with cues off.
TEST_P(MazeGLTest, LabelsShowOnlyWithCuesOff) {
  const Shot s = shot(128);
  const glm::dvec3 start = room_geometry(s.desc).start(s.desc.probe_radius_mm);
  Image on = render(s, scene_of(s, true), start, glm::dvec3(0.0));
  Image off = render(s, scene_of(s, false), start, glm::dvec3(0.0));
  ASSERT_EQ(differing(on, off, 0, 0, on.width, on.height), 0);
  EXPECT_EQ(stamp_label(on, room_label_text(Cue::kNone, true)), glm::ivec2(0, 0));
  const glm::ivec2 box = stamp_label(off, room_label_text(Cue::kNone, false));
  ASSERT_GT(box.x, 0);
  EXPECT_EQ(differing(on, off, 0, 0, on.width, on.height), differing(on, off, 0, 0, box.x, box.y));
  EXPECT_GT(differing(on, off, 0, 0, box.x, box.y), 100);  // the text and its box
}

// The probe beside the hidden sphere, touching it: the frame with the sphere in the scene and
// the frame of the same scene without it are byte-identical (felt, never drawn, and it casts or
// receives no pseudo-shadow either).
TEST_P(MazeGLTest, HiddenSphereDrawsNoPixel) {
  const Shot s = shot(128);
  Scene with = scene_of(s, true), without = with;
  std::size_t removed = 0;
  for (std::size_t i = 0; i < without.surfaces.size(); ++i)
    if (!without.surfaces[i].visible && without.surfaces[i].type == SurfaceType::kSphere) {
      without.surfaces.erase(without.surfaces.begin() + static_cast<std::ptrdiff_t>(i));
      ++removed;
      break;
    }
  ASSERT_EQ(removed, 1u);
  const glm::dvec3 probe = s.room(Cue::kHiddenSphere) +
                           glm::dvec3(s.desc.hidden_offset_mm.x + s.desc.hidden_radius_mm + s.desc.probe_radius_mm,
                                      s.desc.hidden_offset_mm.y, s.desc.hidden_height_mm);
  const Image a = render(s, with, probe, glm::dvec3(0.0)), b = render(s, without, probe, glm::dvec3(0.0));
  EXPECT_EQ(differing(a, b, 0, 0, a.width, a.height), 0);
}

// Largest difference of two frames in 8-bit levels, inside (or outside) a square of `half`
// pixels each way around the image centre (where the camera looks: the floor under the probe).
double max_levels(const Image& a, const Image& b, int half, bool inside) {
  double m = 0.0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const bool in = std::abs(x - a.width / 2) < half && std::abs(y - a.height / 2) < half;
      if (in != inside) continue;
      for (int c = 0; c < 3; ++c) m = std::max(m, 255.0 * std::abs(double(a.at(x, y, c)) - b.at(x, y, c)));
    }
  return m;
}

// The probe 0.5 mm over the floor, moving at the texture's peak speed (lambda x peak_hz), at the
// same place in the texture room and in the dummy room. The rooms are the same geometry moved
// along y, so their frames agree to within one 8-bit level (float rounding of the moved
// coordinates) except where the texture room's material differs: under the probe, its
// pseudo-shadow carries the Gabor texture. Measured (256², llvmpipe, EGL and OSMesa): 43 levels inside
// the 24 px square under the probe; the test asks for 10. Outside it, and everywhere with cues
// off, at most 1 level.
TEST_P(MazeGLTest, TextureRoomShadowIsTextured) {
  const Shot s = shot(256);
  const glm::dvec3 at(20.0, -20.0, s.desc.probe_radius_mm + 0.5);
  const glm::dvec3 v(s.desc.texture_lambda_mm * s.desc.texture_peak_hz, 0.0, 0.0);
  const Scene on = scene_of(s, true), off = scene_of(s, false);
  const Image t_on = render(s, on, s.room(Cue::kTexture) + at, v), d_on = render(s, on, s.room(Cue::kNone) + at, v);
  const double inside = max_levels(t_on, d_on, 12, true);
  RecordProperty("texture_vs_dummy_levels", std::to_string(inside));
  EXPECT_GT(inside, 10.0);
  EXPECT_LE(max_levels(t_on, d_on, 12, false), 1.0);
  const Image t_off = render(s, off, s.room(Cue::kTexture) + at, v), d_off = render(s, off, s.room(Cue::kNone) + at, v);
  EXPECT_LE(std::max(max_levels(t_off, d_off, 12, true), max_levels(t_off, d_off, 12, false)), 1.0);
}

// `maze --every 2`: a pass switch reported on a frame the writer skips still gives the next
// written frame a renderer of the new pass's scene (the switch is reported once).
TEST_P(MazeGLTest, FramesAfterAPassSwitchDrawTheNewPass) {
  const Shot s = shot(64);
  auto pass1 = generate_scene(s.desc, s.route, true, 0), pass2 = generate_scene(s.desc, s.route, true, 1);
  ASSERT_TRUE(pass1 && pass2);
  FrameWriter writer(s.desc, test::temp_dir("frames_switch_" + std::string(gl::backend_name(GetParam()))), 2);
  HapticState st;
  st.proxy_mm = glm::dvec3(0.0, room_geometry(s.desc).hall_y(5), 7.0);
  ASSERT_TRUE(writer.on_frame({0, st, pass1.value(), true, ""}));
  ASSERT_TRUE(writer.on_frame({1, st, pass2.value(), true, ""}));  // not written: odd
  ASSERT_TRUE(writer.on_frame({2, st, pass2.value(), false, ""}));
  ASSERT_NE(writer.renderer(), nullptr);
  EXPECT_EQ(writer.renderer()->scene().path, pass2->scene.path);
  EXPECT_EQ(writer.written(), 2);
}

// The frame the maze drew before it went through run's frame path: the proxy where the loop holds
// it, under the follow camera, nothing else of the world view.
FrameInput proxy_only_input(const MazeDesc& desc, const HapticState& st) {
  FrameInput in;
  if (!st.have_sample) return in;
  in.camera = follow_camera(desc, st.proxy_mm);
  in.probe = ProbeMotion{st.proxy_mm, st.velocity_mm_s};
  return in;
}

// Two renderers of the pass's scene, fed the same states: one the old proxy-only inputs, one
// run's haptic_frame_input with the follow camera (as maze --every and the window draw).
struct TwoPaths {
  MazeDesc desc;
  std::unique_ptr<Renderer> old_path, run_path;
  int frames = 0, pushed = 0;  // frames compared; of them, with the fields pushing the probe
  Status on_frame(const FrameView& v) {
    if (v.scene_changed || !run_path) {
      auto a = Renderer::create(v.scene.scene, RendererOptions{}), b = Renderer::create(v.scene.scene, RendererOptions{});
      if (!a) return a.error();
      if (!b) return b.error();
      old_path = std::move(a.value());
      run_path = std::move(b.value());
    }
    const FrameInput in = haptic_frame_input(*run_path, v.state, {.camera = follow_camera(desc, v.state.proxy_mm)});
    EXPECT_TRUE(in.markers->empty() && in.bodies_mm->empty()) << "frame " << v.index;
    EXPECT_EQ(*in.view, ViewPose{}) << "frame " << v.index;
    if (auto f = old_path->render(proxy_only_input(desc, v.state)); !f) return f.error();
    if (auto f = run_path->render(in); !f) return f.error();
    const Image a = old_path->read_color(), b = run_path->read_color();
    EXPECT_TRUE(a.pixels == b.pixels) << "frame " << v.index << " differs";
    ++frames;
    pushed += glm::length(v.state.field_force_n) > 0.01 ? 1 : 0;
    return ok_status();
  }
};

// Through run's frame path the maze's frames stay what its sessions drew, byte for byte: a
// scripted participant through the shipped maze, every cue's room on the way (the external-force
// room's field pushing the probe, which a charge scene would show as an arrow).
TEST_P(MazeGLTest, FramesThroughRunsFramePathAreTheProxyOnlyFrames) {
  Shot s = shot(64);
  for (const bool cues : {true, false}) {
    const std::string dir = test::temp_dir("two_paths_" + std::string(gl::backend_name(GetParam())) + (cues ? "_on" : "_off"));
    std::ofstream(dir + "/p.traj") << script_trajectory(s.desc, {choices_with_errors(s.route, 0, 2)}, 300.0);
    auto dev = open_log_device("trajectory:" + dir + "/p.traj");
    ASSERT_TRUE(dev) << dev.error().message;
    SessionOptions o;
    o.desc = s.desc;
    o.route = s.route;
    o.info.participant = "T";
    o.info.seed = s.route.seed;
    o.info.cues = cues;
    o.log_path = dir + "/session.jsonl";
    o.fps = 4.0;
    TwoPaths two;
    two.desc = s.desc;
    auto r = run_session(*dev.value(), o, [&two](const FrameView& v) { return two.on_frame(v); }, nullptr);
    ASSERT_TRUE(r) << r.error().message;
    RecordProperty(cues ? "frames_cues_on" : "frames_cues_off", std::to_string(two.frames));
    RecordProperty(cues ? "pushed_cues_on" : "pushed_cues_off", std::to_string(two.pushed));
    EXPECT_GT(two.frames, 20);
    if (cues) {
      EXPECT_GT(two.pushed, 0);  // the external-force room was drawn with its field pushing
    }
  }
}

PS_INSTANTIATE_HEADLESS_BACKENDS(MazeGLTest);

}  // namespace
}  // namespace ps::maze
