// The pointer mapping without GL or a window: the shadow's centre (the hit point) projects back
// to the pointer on perspective and orthographic cameras, zoomed and orbited; rays that miss the
// plane keep the last position; the height keys step by the stated step; the pointer log.
#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cmath>
#include <limits>
#include <vector>

#include "app/window/window_input.h"
#include "devices/pointer_map.h"
#include "devices/sample_log.h"

namespace ps {
namespace {

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The default scene's camera: 45 degrees above a plank at z = 0, 59 mm from the target.
PointerView perspective_view(double zoom) {
  PointerView v;
  v.camera.position = glm::dvec3(0.0, -42.0, 42.0) / zoom;
  v.camera.fov_y_deg = 40.0;
  v.window_size = {640.0, 480.0};
  v.aspect = 640.0 / 480.0;
  return v;
}

PointerView orthographic_view(double height_mm) {
  PointerView v;
  v.camera.projection = Projection::kOrthographic;
  v.camera.position = {0.0, 0.0, 200.0};
  v.camera.up = {0.0, 1.0, 0.0};
  v.camera.ortho_height_mm = height_mm;
  v.window_size = {512.0, 512.0};
  return v;
}

PointerView orbited(PointerView v, double azimuth_rad, double elevation_rad, double distance_mm) {
  v.camera.target = {5.0, -3.0, 0.0};
  v.camera.up = {0.0, 0.0, 1.0};
  v.camera.position = v.camera.target + distance_mm * glm::dvec3(std::cos(elevation_rad) * std::cos(azimuth_rad),
                                                                 std::cos(elevation_rad) * std::sin(azimuth_rad),
                                                                 std::sin(elevation_rad));
  return v;
}

struct Case {
  const char* name;
  PointerView view;
};

std::vector<Case> cases() {
  return {{"perspective", perspective_view(1.0)},
          {"perspective zoomed in 2x", perspective_view(2.0)},
          {"perspective orbited", orbited(perspective_view(1.0), -0.7, 0.5, 80.0)},
          {"orthographic 100 mm", orthographic_view(100.0)},
          {"orthographic 25 mm", orthographic_view(25.0)},
          {"orthographic orbited", orbited(orthographic_view(60.0), 2.0, 0.9, 150.0)}};
}

TEST(PointerMapTest, ShadowCentreProjectsBackToThePointer) {
  for (const Case& c : cases()) {
    for (double fx : {0.013, 0.25, 0.5, 0.77, 0.999})
      for (double fy : {0.02, 0.5, 0.61, 0.98}) {
        const glm::dvec2 pointer(fx * c.view.window_size.x, fy * c.view.window_size.y);
        for (double height : {-2.0, 1.5, 30.0}) {
          PointerMap map;
          const glm::dvec3 centre = map.absolute(c.view, pointer, height);
          ASSERT_TRUE(map.have_hit()) << c.name;
          const glm::dvec3 hit = map.hit(c.view);
          // The probe hovers over the hit point: its lowest point is `height` above it.
          EXPECT_NEAR(glm::dot(centre - hit, c.view.plane.n), c.view.probe_radius_mm + height, 1e-9) << c.name;
          EXPECT_NEAR(glm::length(centre - hit), c.view.probe_radius_mm + height, 1e-9) << c.name;
          // 1e-9 mm: the hit is computed on the plane; only rounding moves it off.
          EXPECT_NEAR(glm::dot(hit - c.view.plane.origin, c.view.plane.n), 0.0, 1e-9) << c.name;
          const glm::dvec2 back = project_to_window(c.view, hit);
          // 1e-6 px: double-precision inverse and forward matrices agree far below that.
          EXPECT_NEAR(back.x, pointer.x, 1e-6) << c.name << " at " << fx << "," << fy;
          EXPECT_NEAR(back.y, pointer.y, 1e-6) << c.name << " at " << fx << "," << fy;
        }
      }
  }
}

TEST(PointerMapTest, OrthographicTopViewMatchesTheClosedForm) {
  // Straight down, up = +y: window x runs along +x, window y along -y, ortho_height_mm tall.
  const PointerView v = orthographic_view(40.0);
  PointerMap map;
  map.absolute(v, {128.0, 64.0}, 0.0);
  const glm::dvec3 hit = map.hit(v);
  EXPECT_NEAR(hit.x, (128.0 / 512.0 - 0.5) * 40.0, 1e-9);  // -10 mm
  EXPECT_NEAR(hit.y, (0.5 - 64.0 / 512.0) * 40.0, 1e-9);   // +15 mm
  EXPECT_NEAR(hit.z, 0.0, 1e-9);
}

TEST(PointerMapTest, PerspectiveWindowCentreIsTheTargetAndEdgesSpanTheFieldOfView) {
  const PointerView v = perspective_view(1.0);  // target (0,0,0) lies on the plane
  PointerMap map;
  map.absolute(v, 0.5 * v.window_size, 0.0);
  EXPECT_NEAR(glm::length(map.hit(v)), 0.0, 1e-9);
  // The top edge of the window is fov/2 above the view axis (independent of the matrices).
  map.absolute(v, {0.5 * v.window_size.x, 0.0}, 0.0);
  const glm::dvec3 to_hit = glm::normalize(map.hit(v) - v.camera.position);
  const glm::dvec3 axis = glm::normalize(v.camera.target - v.camera.position);
  EXPECT_NEAR(std::acos(glm::dot(to_hit, axis)), glm::radians(20.0), 1e-9);
}

TEST(PointerMapTest, RayParallelToOrAwayFromThePlaneKeepsTheLastPosition) {
  PointerView v = perspective_view(1.0);
  v.camera.position = {0.0, -100.0, 0.5};  // eye just above the plane z = 0, looking along +y
  v.camera.target = {0.0, 0.0, 0.5};
  PointerMap map;
  const glm::dvec3 good = map.absolute(v, {320.0, 400.0}, 1.5);  // below the horizon: hits
  ASSERT_TRUE(map.have_hit());
  EXPECT_TRUE(finite(good));
  // The window's middle row looks along the plane (parallel), the top half away from it.
  for (const glm::dvec2 p : {glm::dvec2(320.0, 240.0), glm::dvec2(100.0, 240.0), glm::dvec2(320.0, 10.0)}) {
    EXPECT_FALSE(intersect_plane(pointer_ray(v, p), v.plane).has_value()) << p.x << "," << p.y;
    const glm::dvec3 kept = map.absolute(v, p, 1.5);
    EXPECT_EQ(kept, good) << p.x << "," << p.y;
  }
}

TEST(PointerMapTest, PointerOutsideTheWindowNeverGivesNan) {
  for (const Case& c : cases()) {
    PointerMap map;
    const glm::dvec3 start = map.absolute(c.view, {-1.0, -1.0}, 1.5);  // before any hit: the plane origin
    EXPECT_TRUE(finite(start)) << c.name;
    const double inf = std::numeric_limits<double>::infinity();
    for (const glm::dvec2 p : {glm::dvec2(-1e6, -1e6), glm::dvec2(1e9, 5.0), glm::dvec2(3000.0, -4000.0),
                               glm::dvec2(std::nan(""), 10.0), glm::dvec2(inf, -inf), glm::dvec2(-5.0, 1e300)}) {
      const glm::dvec3 pos = map.absolute(c.view, p, 1.5);
      EXPECT_TRUE(finite(pos)) << c.name << " at " << p.x << "," << p.y;
    }
  }
}

TEST(PointerMapTest, RelativeMotionIsScreenAlignedAtTheStatedScale) {
  const PointerView v = perspective_view(1.0);
  PointerMap map;
  map.absolute(v, 0.5 * v.window_size, 1.0);
  const glm::dvec3 before = map.hit(v);
  map.relative(v, {50.0, 0.0}, 0.1, 1.0);  // 50 counts right
  EXPECT_NEAR(glm::length(map.hit(v) - before), 5.0, 1e-9);  // 50 x 0.1 mm
  const glm::dvec2 a = project_to_window(v, before), b = project_to_window(v, map.hit(v));
  EXPECT_GT(b.x - a.x, 10.0) << "moved right on screen";
  EXPECT_NEAR(b.y, a.y, 1e-6) << "a horizontal motion stays on its row (camera roll-free)";
  map.relative(v, {0.0, -20.0}, 0.1, 1.0);  // 20 counts up the screen
  EXPECT_LT(project_to_window(v, map.hit(v)).y, b.y);
}

TEST(PointerMapTest, HeightIsClampedToItsStatedLimits) {
  HeightControl h(HeightParams{});
  EXPECT_EQ(h.mm(), 1.0);
  h.scroll(-3.0);
  EXPECT_DOUBLE_EQ(h.mm(), -0.5);
  h.step(-100);
  EXPECT_EQ(h.mm(), -4.0);
  h.set(std::nan(""));
  EXPECT_EQ(h.mm(), -4.0);
  h.step(1000);
  EXPECT_EQ(h.mm(), 60.0);
}

TEST(WindowInputTest, EachPressAndRepeatStepsTheHeightByTheStep) {
  WindowInput in;
  HeightControl h(HeightParams{});
  const double start = h.mm();
  constexpr int kPresses = 7;
  for (int i = 0; i < kPresses; ++i) {
    handle_key(in, GLFW_KEY_PAGE_DOWN, GLFW_PRESS, 0);
    handle_key(in, GLFW_KEY_PAGE_DOWN, GLFW_RELEASE, 0);  // a release is not a step
  }
  h.step(in.height_steps);
  in.height_steps = 0;
  EXPECT_DOUBLE_EQ(h.mm(), start - kPresses * 0.5);
  // Held: one press then the system's repeats, each a step; the arrow keys do the same.
  handle_key(in, GLFW_KEY_UP, GLFW_PRESS, 0);
  for (int i = 0; i < 4; ++i) handle_key(in, GLFW_KEY_UP, GLFW_REPEAT, 0);
  handle_key(in, GLFW_KEY_PAGE_UP, GLFW_PRESS, 0);
  EXPECT_EQ(in.height_steps, 6);
  // Repeats of the other keys do nothing more: one screenshot per press.
  handle_key(in, GLFW_KEY_S, GLFW_PRESS, 0);
  handle_key(in, GLFW_KEY_S, GLFW_REPEAT, 0);
  EXPECT_EQ(in.screenshots, 1);
  // While the panel has the keyboard the height keys are the panel's.
  in.keys_captured = true;
  handle_key(in, GLFW_KEY_PAGE_UP, GLFW_PRESS, 0);
  EXPECT_EQ(in.height_steps, 6);
}

TEST(WindowInputTest, PlainScrollMovesTheHeightShiftScrollZooms) {
  WindowInput in;
  handle_scroll(in, -3.0, false);
  handle_scroll(in, 2.0, true);
  EXPECT_EQ(in.scroll_height, -3.0);
  EXPECT_EQ(in.scroll_zoom, 2.0);
}

// The window's events as its LiveWindow delivers them (app/window/window_listener.h), no window.
TEST(WindowInputTest, TheRightButtonDragsTheOrbitOtherButtonsDoNot) {
  WindowInput in;
  in.on_cursor(10.0, 10.0);
  in.on_mouse_button(GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, 10.0, 10.0);  // the probe's, not the camera's
  in.on_cursor(30.0, 10.0);
  EXPECT_EQ(in.orbit_dx, 0.0);
  in.on_mouse_button(GLFW_MOUSE_BUTTON_RIGHT, GLFW_PRESS, 30.0, 10.0);
  in.on_cursor(35.0, 2.0);
  in.on_mouse_button(GLFW_MOUSE_BUTTON_RIGHT, GLFW_RELEASE, 35.0, 2.0);
  in.on_cursor(90.0, 90.0);  // released: no more orbit
  EXPECT_EQ(in.orbit_dx, 5.0);
  EXPECT_EQ(in.orbit_dy, -8.0);
}

TEST(WindowInputTest, ThePointerOrFocusComingBackIsRegainedOnce) {
  WindowInput in;
  in.on_enter(true);  // already inside: nothing regained
  EXPECT_FALSE(in.regained);
  in.on_enter(false);
  EXPECT_FALSE(in.pointer_inside);
  in.on_enter(true);
  EXPECT_TRUE(in.regained && in.pointer_inside);
  in.regained = false;  // the frame took it
  in.on_focus(false);
  in.on_focus(true);
  EXPECT_TRUE(in.regained && in.focused);
  in.on_char('?');
  EXPECT_TRUE(in.toggle_help);
}

TEST(PointerLogTest, ErrorsNameTheFileAndLineAndTheFields) {
  auto r = parse_pointer_log("# pointer\n0 10 20 1.5 0\n0.5 30 40\n", "move.ptr");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message, "move.ptr:3: expected 5 fields 'time_s x_px y_px height_mm buttons', got 3");
  auto bad = parse_pointer_log("0 10 abc 1.5 0\n", "move.ptr");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().message, "move.ptr:1: y_px: not a number: 'abc'");
  EXPECT_FALSE(open_pointer_device("trajectory:x.traj").ok());
}

TEST(PointerLogTest, MapsLikeTheMouseOnceItHasAView) {
  auto samples = parse_pointer_log("0 100 100 2 1\n1 300 200 0 0\n", "move.ptr");
  ASSERT_TRUE(samples.ok());
  PointerLogDevice dev(samples.value(), "pointer:move.ptr");
  EXPECT_FALSE(dev.read(0.0).valid) << "no view yet: nothing to map through";
  const PointerView v = perspective_view(1.0);
  dev.set_view(v);
  const DeviceSample s = dev.read(0.5);  // halfway: (200, 150) px, 1 mm
  ASSERT_TRUE(s.valid);
  EXPECT_EQ(s.buttons, 1u);
  PointerMap expected;
  const glm::dvec3 want = expected.absolute(v, {200.0, 150.0}, 1.0);
  EXPECT_NEAR(glm::length(s.position_mm - want), 0.0, 1e-12);
  const glm::dvec2 back = project_to_window(v, s.position_mm - (v.probe_radius_mm + 1.0) * v.plane.n);
  EXPECT_NEAR(back.x, 200.0, 1e-6);
  EXPECT_NEAR(back.y, 150.0, 1e-6);
}

}  // namespace
}  // namespace ps
