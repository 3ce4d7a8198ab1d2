// The frame key and the redrawn rectangle (render/frame_key.h), without GL: a field only the
// pseudo-shadow variant reads leaves the key alone, anything the plain variant reads or a
// different mesh changes it, and the redrawn pixels follow.
#include <gtest/gtest.h>

#include "render/frame_key.h"

namespace ps {
namespace {

FrameKey key_of(const std::vector<SurfaceDraw>& draws) { return make_frame_key({&draws, glm::dvec3(0.1), 64, 48, 0, 1.0}); }

TEST(FrameKeyTest, ProbeOnlyFieldsLeaveTheKeyAlone) {
  const std::vector<SurfaceDraw> base(2);
  const FrameKey k = key_of(base);
  for (auto change : std::vector<void (*)(SurfaceBlock&)>{
           [](SurfaceBlock& b) { b.window.x += 1.0f; }, [](SurfaceBlock& b) { b.probe_a.z -= 0.5f; },
           [](SurfaceBlock& b) { b.probe_b.w = 1.0f; }, [](SurfaceBlock& b) { b.modulation.x = 0.3f; },
           [](SurfaceBlock& b) { b.ref_t.w = 2.0f; }, [](SurfaceBlock& b) { b.gabor.kernel.w = 5.0f; }}) {
    std::vector<SurfaceDraw> d = base;
    change(d[1].block);
    EXPECT_EQ(key_of(d), k);
  }
}

TEST(FrameKeyTest, WhatThePlainVariantReadsChangesTheKey) {
  const std::vector<SurfaceDraw> base(2);
  const FrameKey k = key_of(base);
  for (auto change : std::vector<void (*)(SurfaceBlock&)>{
           [](SurfaceBlock& b) { b.view_proj[3][0] += 1e-3f; }, [](SurfaceBlock& b) { b.light_dir.y = 0.5f; },
           [](SurfaceBlock& b) { b.albedo.x = 0.9f; }, [](SurfaceBlock& b) { b.intensity.w = 3.0f; },
           [](SurfaceBlock& b) { b.body_spheres[1].x = 4.0f; }, [](SurfaceBlock& b) { b.sheet.y = 0.2f; },
           [](SurfaceBlock& b) { b.cutaway.w = 1.0f; }, [](SurfaceBlock& b) { b.ref_n.z = 1.0f; }}) {
    std::vector<SurfaceDraw> d = base;
    change(d[1].block);
    EXPECT_NE(key_of(d), k);
  }
  std::vector<SurfaceDraw> d = base;
  d.pop_back();
  EXPECT_NE(key_of(d), k);  // a surface less
  static const int another = 0;  // a mesh's address only (the key never reads the mesh)
  d = base;
  d[0].mesh = reinterpret_cast<const GpuMesh*>(&another);
  EXPECT_NE(key_of(d), k);  // another mesh
  EXPECT_NE(make_frame_key({&base, glm::dvec3(0.1), 64, 48, 1, 1.0}), k);    // a deformed mesh uploaded
  EXPECT_NE(make_frame_key({&base, glm::dvec3(0.1), 64, 48, 0, 0.5}), k);    // a tile half baked
  EXPECT_NE(make_frame_key({&base, glm::dvec3(0.2), 64, 48, 0, 1.0}), k);    // the background
}

TEST(FrameKeyTest, HistoryRedrawsTheUnionOfTheRectanglesOrEverything) {
  const std::vector<SurfaceDraw> draws(1);
  const PixelRect whole = PixelRect::whole(64, 48), a{10, 10, 20, 20}, b{15, 5, 30, 18};
  FrameHistory h;
  EXPECT_EQ(h.redraw(key_of(draws), a, 64, 48, true), whole);  // nothing kept yet
  EXPECT_EQ(h.redraw(key_of(draws), b, 64, 48, true), (PixelRect{10, 5, 30, 20}));
  EXPECT_EQ(h.redraw(key_of(draws), PixelRect{}, 64, 48, true), b);  // the shadow left: its old pixels
  EXPECT_EQ(h.redraw(key_of(draws), PixelRect{}, 64, 48, true), PixelRect{});
  h.invalidate();
  EXPECT_EQ(h.redraw(key_of(draws), a, 64, 48, true), whole);
  std::vector<SurfaceDraw> other(1);
  other[0].block.albedo.y = 0.7f;
  EXPECT_EQ(h.redraw(key_of(other), a, 64, 48, true), whole);
  EXPECT_EQ(h.redraw(key_of(other), a, 64, 48, false), whole);  // incremental frames off
  EXPECT_EQ(h.redraw(key_of(other), a, 64, 48, true), whole);   // after a full frame by request
}

}  // namespace
}  // namespace ps
