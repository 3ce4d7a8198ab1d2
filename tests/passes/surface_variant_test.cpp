// SurfaceVariantTest (no GL): the surface pass's variants by name give the #define lines the
// sources were always built with, and a draw's request reduces to a valid set.
#include "passes/surface_variant.h"

#include <gtest/gtest.h>

namespace ps {
namespace {

using F = SurfaceFlag;

TEST(SurfaceVariantTest, PlainAndShadowKeepTheirTwoDefines) {
  EXPECT_EQ(defines_for({}), (gl::Defines{{"PS_SHADOW", "0"}, {"PS_TEXTURED", "0"}}));
  EXPECT_EQ(defines_for(F::kShadow | F::kTextured), (gl::Defines{{"PS_SHADOW", "1"}, {"PS_TEXTURED", "1"}}));
}

TEST(SurfaceVariantTest, ExtraDefinesFollowInTheirFixedOrder) {
  const gl::Defines d =
      defines_for(F::kShadow | F::kTextured | F::kBakedLinear | F::kFilterSkipped | F::kIntensityLut);
  EXPECT_EQ(d, (gl::Defines{{"PS_SHADOW", "1"},
                            {"PS_TEXTURED", "1"},
                            {"PS_GABOR_BAKED", "2"},
                            {"PS_GABOR_FILTER", "2"},
                            {"PS_INTENSITY_LUT", "1"}}));
  EXPECT_EQ(defines_for(F::kShadow | F::kTextured | F::kStratified | F::kFilter),
            (gl::Defines{{"PS_SHADOW", "1"}, {"PS_TEXTURED", "1"}, {"PS_GABOR_STRATIFIED", "1"}, {"PS_GABOR_FILTER", "1"}}));
}

TEST(SurfaceVariantTest, NoShadowDropsEveryTextureFlag) {
  const SurfaceFlags v = surface_variant({false, true, true, 1, 2, true});
  EXPECT_EQ(v, SurfaceFlags(F::kIntensityLut));
}

TEST(SurfaceVariantTest, UntexturedShadowDropsTheGaborFlags) {
  EXPECT_EQ(surface_variant({true, false, true, 2, 1, false}), SurfaceFlags(F::kShadow));
}

TEST(SurfaceVariantTest, ATileReplacesStratifiedImpulses) {
  EXPECT_EQ(surface_variant({true, true, true, 1, 0, false}), F::kShadow | F::kTextured | F::kBakedHermite);
  EXPECT_EQ(surface_variant({true, true, true, 0, 0, false}), F::kShadow | F::kTextured | F::kStratified);
}

TEST(SurfaceVariantTest, DistinctRequestsGiveDistinctKeys) {
  EXPECT_NE(surface_variant({true, true, false, 0, 1, false}), surface_variant({true, true, false, 0, 2, false}));
  EXPECT_NE(surface_variant({true, true, false, 1, 0, false}), surface_variant({true, true, false, 2, 0, false}));
}

}  // namespace
}  // namespace ps
