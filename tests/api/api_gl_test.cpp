// The C++ API's own behaviour (include/pseudoshadow/pseudoshadow.h): what the Python suite and
// the package tests do not reach. Equality with the CLI is checked there (tests/python,
// api.install_consumer); here: one GL backend per process, set() keeping the probe and failing
// without a change, the errors' words.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "pseudoshadow/pseudoshadow.h"

namespace {

namespace psa = pseudoshadow;

psa::OpenDesc small(psa::Backend backend) {
  psa::OpenDesc desc;
  desc.backend = backend;
  desc.set = {"render.size=[32,32]"};
  return desc;
}

std::string error_of(auto&& call) {
  try {
    call();
  } catch (const psa::Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ApiGLTest, OneBackendPerProcessAtATime) {
  {
    psa::Renderer egl = psa::Renderer::open_default(small(psa::Backend::kEgl));
    EXPECT_EQ(egl.render().stats.backend, "egl");
    // auto shares the open context; another backend is refused with what to do.
    psa::Renderer shared = psa::Renderer::open_default(small(psa::Backend::kAuto));
    EXPECT_EQ(shared.render().stats.backend, "egl");
    EXPECT_EQ(error_of([] { psa::Renderer::open_default(small(psa::Backend::kOsmesa)); }),
              "backend osmesa: a renderer on egl is open, and a process has one GL backend at a time: "
              "close the other renderers first, or open this one with backend auto or egl");
    // Both still render after the refusal (the refused context was never created).
    EXPECT_GT(egl.render().stats.shadow_pixels, 0u);
    EXPECT_GT(shared.render().stats.shadow_pixels, 0u);
  }
  // Once all are closed, another backend opens.
  psa::Renderer osmesa = psa::Renderer::open_default(small(psa::Backend::kOsmesa));
  EXPECT_EQ(osmesa.render().stats.backend, "osmesa");
}

TEST(ApiGLTest, SetKeepsTheProbeAndAFailedSetChangesNothing) {
  psa::Renderer r = psa::Renderer::open_default(small(psa::Backend::kAuto));
  r.set_probe({1, 2, 7.5}, {10, 0, 0});
  r.set("materials.wood.lambda_min", "0.4");
  EXPECT_EQ(r.probe().first, (psa::Vec3{1, 2, 7.5}));
  EXPECT_EQ(r.probe().second, (psa::Vec3{10, 0, 0}));
  r.set("probe.position=[0,0,9]");  // this key does move it
  EXPECT_EQ(r.probe().first, (psa::Vec3{0, 0, 9}));

  EXPECT_EQ(error_of([&] { r.set_all({"materials.wood.lambda_min=0.9", "render.size=[32,0]"}); }).rfind("--set render.size", 0),
            0u);
  EXPECT_EQ(r.size(), (std::pair<int, int>{32, 32}));
  EXPECT_EQ(error_of([&] { r.set("materials.wood.lambda_min"); }),
            "--set materials.wood.lambda_min: expected KEY=VALUE, e.g. materials.wood.lambda_min=0.4");
}

TEST(ApiGLTest, ErrorsSayWhatToDo) {
  psa::Renderer r = psa::Renderer::open_default(small(psa::Backend::kAuto));
  psa::RenderDesc with_distance;
  with_distance.aovs = {"distance"};
  const psa::Frame f = r.render(with_distance);
  EXPECT_EQ(f.aov("distance").channels, 1);
  EXPECT_EQ(f.aov("distance").pixels.size(), 32u * 32u);
  EXPECT_EQ(error_of([&] { (void)f.aov("normal"); }),
            "AOV 'normal' was not rendered (asked for: distance); name it in RenderDesc::aovs");
  psa::RenderDesc negative;
  negative.frames = -1;
  EXPECT_EQ(error_of([&] { r.render(negative); }),
            "--frames: -1 is not a frame count; use 1 or more (or 0 for the scene's render.frames)");
  EXPECT_EQ(error_of([] { psa::Renderer::open_file("no/such/scene.toml"); }),
            "no/such/scene.toml: cannot open scene file: no such file");
  psa::Renderer moved = std::move(r);
  EXPECT_EQ(error_of([&] { r.render(); }),  // NOLINT(bugprone-use-after-move): the point
            "pseudoshadow::Renderer::render: this renderer was moved from");
}

}  // namespace

// nearest_surface on the default scene's plank (top at z = 0, 200 x 120 mm, normal +z), in
// closed form: above it, beside its edge, out of range, a NaN point. Exact up to rounding (the
// plank is analytic, no mesh): 1e-9 mm.
TEST(ApiGLTest, NearestSurfaceIsTheFeltGeometryInClosedForm) {
  psa::Renderer r = psa::Renderer::open_default(small(psa::Backend::kAuto));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<psa::SurfacePoint> s = r.nearest_surface({{10, 5, 12}, {130, 0, 0}, {0, 0, 5000}, {nan, 0, 0}});
  ASSERT_EQ(s.size(), 4u);
  EXPECT_NEAR(s[0].distance_mm, 12.0, 1e-9);
  EXPECT_NEAR(s[0].point[0], 10.0, 1e-9);
  EXPECT_NEAR(s[0].point[1], 5.0, 1e-9);
  EXPECT_NEAR(s[0].point[2], 0.0, 1e-9);
  EXPECT_NEAR(s[0].normal[2], 1.0, 1e-9);
  EXPECT_NEAR(s[1].distance_mm, 30.0, 1e-9);  // the plank's edge at x = 100
  EXPECT_NEAR(s[1].point[0], 100.0, 1e-9);
  EXPECT_TRUE(std::isinf(s[2].distance_mm));  // beyond the default 1000 mm
  EXPECT_EQ(s[2].point, (psa::Vec3{0, 0, 0}));
  EXPECT_TRUE(std::isinf(s[3].distance_mm));
  EXPECT_NEAR(r.nearest_surface({{0, 0, 5000}}, 6000.0)[0].distance_mm, 5000.0, 1e-9);
  // set() moves the geometry with the scene.
  r.set("surfaces.0.center", "[0, 0, -3]");
  EXPECT_NEAR(r.nearest_surface({{10, 5, 12}})[0].distance_mm, 15.0, 1e-9);
  EXPECT_EQ(error_of([&] { r.nearest_surface({{0, 0, 0}}, 0.0); }),
            "nearest_surface: max_distance_mm must be a positive number of mm, not 0");
}
