// The sheet a hovering probe's shadow falls on (render/surface_geometry.h, nearest_w), without GL:
// the w of the surface point nearest the probe, not of the nearest vertex.
#include <gtest/gtest.h>

#include <cmath>

#include "render/surface_geometry.h"

namespace ps {
namespace {

// Two sheets as a surface embedded in 4D has them where they cross in the picture: A, a large
// triangle in z = 0 at w = +1, whose vertices are all ~100 mm away; B, at w = -1, with a vertex
// 5 mm from the probe. The probe hovers 4 mm over A: A is nearest (4 mm), B's vertex is the
// nearest vertex (5 mm against A's ~100 mm). Lowered, the probe touches A, and its shadow
// belongs there; the nearest vertex would put it on B (no shadow on the sheet seen).
TEST(SurfaceGeometryTest, AHoveringProbesSheetIsTheNearestSurfacePointsNotTheNearestVertexs) {
  SurfaceGeometry g;
  g.sheet_positions = {{-100.0f, -100.0f, 0.0f}, {100.0f, -100.0f, 0.0f}, {0.0f, 100.0f, 0.0f},  // A
                       {3.0f, 0.0f, 8.0f}, {200.0f, 0.0f, 300.0f}, {3.0f, 200.0f, 300.0f}};     // B
  g.sheet_indices = {0, 1, 2, 3, 4, 5};
  g.w4 = {1.0f, 1.0f, 1.0f, -1.0f, -1.0f, -1.0f};
  const glm::dvec3 probe(0.0, 0.0, 4.0);
  EXPECT_DOUBLE_EQ(g.nearest_w(probe, 0.0), 1.0);
  // Over B's vertex instead (1 mm from it, 9 mm over A): B.
  EXPECT_DOUBLE_EQ(g.nearest_w({3.0, 0.0, 9.0}, 0.0), -1.0);
}

// Within the nearest triangle the w is its nearest corner's (a w that changed with every move of
// the probe would redraw every pixel of every frame: the sheet's w is part of the frame key).
TEST(SurfaceGeometryTest, TheWIsTheNearestTrianglesNearestCorners) {
  SurfaceGeometry g;
  g.sheet_positions = {{0.0f, 0.0f, 0.0f}, {40.0f, 0.0f, 0.0f}, {0.0f, 40.0f, 0.0f}};
  g.sheet_indices = {0, 1, 2};
  g.w4 = {0.0f, 2.0f, 4.0f};
  EXPECT_EQ(g.nearest_w({10.0, 20.0, 3.0}, -9.0), 4.0) << "barycentric (1/4, 1/4, 1/2)";
  EXPECT_EQ(g.nearest_w({11.0, 20.0, 3.0}, -9.0), 4.0) << "a mm along: the same w";
  EXPECT_EQ(g.nearest_w({30.0, 2.0, 3.0}, -9.0), 2.0);
  EXPECT_EQ(g.nearest_w({std::nan(""), 0.0, 0.0}, -9.0), -9.0) << "a NaN probe keeps the fallback";
  EXPECT_EQ(SurfaceGeometry{}.nearest_w({1.0, 2.0, 3.0}, -9.0), -9.0) << "no triangles: the fallback";
}

}  // namespace
}  // namespace ps
