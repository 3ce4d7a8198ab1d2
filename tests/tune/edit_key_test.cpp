// EditKey (tune/edit_key.h): a scene key parsed once, its text unchanged.
#include "tune/edit_key.h"

#include <gtest/gtest.h>

namespace ps {
namespace {

TEST(EditKeyTest, SplitsSectionMaterialAndField) {
  const EditKey k = EditKey::parse("materials.wood.lambda_max");
  EXPECT_EQ(k.text(), "materials.wood.lambda_max");
  EXPECT_EQ(k.section(), "materials");
  EXPECT_EQ(k.material(), "wood");
  EXPECT_EQ(k.field(), "lambda_max");
  EXPECT_EQ(k.curve(), CurveKind::kNone);
  EXPECT_FALSE(k.camera());
}

TEST(EditKeyTest, CameraKeysAreCameraKeys) {
  EXPECT_TRUE(EditKey::parse("camera.position").camera());
  EXPECT_TRUE(EditKey::parse("camera.fov_y_deg").camera());
  EXPECT_FALSE(EditKey::parse("cameras.position").camera());
  EXPECT_FALSE(EditKey::parse("probe.position").camera());
  EXPECT_EQ(EditKey::parse("probe.position").material(), "");
}

TEST(EditKeyTest, CurvesRoundTripThroughTheirText) {
  const EditKey i = EditKey::curve("table4_1_a", CurveKind::kIntensity);
  EXPECT_EQ(i.text(), "materials.table4_1_a.intensity_lut");
  EXPECT_EQ(EditKey::parse(i.text()).curve(), CurveKind::kIntensity);
  const EditKey g = EditKey::curve("a.b", CurveKind::kSpeedGain);  // a name with a dot keeps it
  EXPECT_EQ(g.text(), "materials.a.b.speed_gain_lut");
  EXPECT_EQ(EditKey::parse(g.text()).material(), "a.b");
  EXPECT_EQ(EditKey::parse(g.text()).curve(), CurveKind::kSpeedGain);
  // Only a material's *_lut keys are curves.
  EXPECT_EQ(EditKey::parse("materials.intensity_lut").curve(), CurveKind::kNone);
  EXPECT_EQ(EditKey::parse("render.intensity_lut").curve(), CurveKind::kNone);
}

TEST(EditKeyTest, AKeyWithoutDotsIsAllSectionAndField) {
  const EditKey k = EditKey::parse("seed");
  EXPECT_EQ(k.section(), "seed");
  EXPECT_EQ(k.field(), "seed");
  EXPECT_EQ(k.material(), "");
}

}  // namespace
}  // namespace ps
