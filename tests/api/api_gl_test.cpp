// The C++ API's own behaviour (include/pseudoshadow/pseudoshadow.h): what the Python suite and
// the package tests do not reach. Equality with the CLI is checked there (tests/python,
// api.install_consumer); here: one GL backend per process, set() keeping the probe and failing
// without a change, the errors' words.
#include <gtest/gtest.h>

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
