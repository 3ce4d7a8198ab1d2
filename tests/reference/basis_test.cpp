#include <gtest/gtest.h>

#include "reference/basis.h"

namespace ps {
namespace {

TEST(PlaneFrameTest, OrthonormalForManyNormals) {
  for (double x = -1.0; x <= 1.0; x += 0.25)
    for (double y = -1.0; y <= 1.0; y += 0.25)
      for (double z : {-1.0, -0.3, 0.0, 0.2, 1.0}) {
        if (x == 0 && y == 0 && z == 0) continue;
        const PlaneFrame f = make_plane_frame({x, y, z});
        EXPECT_NEAR(glm::length(f.t), 1.0, 1e-12);
        EXPECT_NEAR(glm::length(f.b), 1.0, 1e-12);
        EXPECT_NEAR(glm::dot(f.t, f.b), 0.0, 1e-12);
        EXPECT_NEAR(glm::dot(f.t, f.n), 0.0, 1e-12);
        // Right-handed: t x b = n, so (u, v, h) is a proper rotation of (x, y, z).
        EXPECT_NEAR(glm::length(glm::cross(f.t, f.b) - f.n), 0.0, 1e-12);
      }
}

TEST(PlaneFrameTest, PlusZIsIdentity) {
  const PlaneFrame f = make_plane_frame({0, 0, 1});
  EXPECT_EQ(f.t, glm::dvec3(1, 0, 0));
  EXPECT_EQ(f.b, glm::dvec3(0, 1, 0));
}

}  // namespace
}  // namespace ps
