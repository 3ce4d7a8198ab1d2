// ImageCompareTest: thresholds, failing-pixel budget, size mismatch, diff image. No GL needed.
#include <cmath>

#include <gtest/gtest.h>

#include "image/image.h"
#include "image_test_util.h"

namespace ps {
namespace {

TEST(ImageCompareTest, IdenticalImagesPassWithZeroError) {
  const Image a = test::gradient_image(8, 8, 4);
  Result<CompareResult> r = compare_images(a, a, CompareOptions{});
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_TRUE(r->passed);
  EXPECT_EQ(r->max_abs, 0.0);
  EXPECT_EQ(r->mean_abs, 0.0);
  EXPECT_EQ(r->failing_pixels, 0);
  EXPECT_EQ(r->failing_percent, 0.0);
}

TEST(ImageCompareTest, OneChangedPixelAboveThresholdFails) {
  const Image a = test::constant_image(10, 10, 3, 0.5f);
  Image b = a;
  b.at(3, 7, 1) += 0.1f;
  Result<CompareResult> r = compare_images(a, b, CompareOptions{.fail_threshold = 0.05f, .fail_percent = 0.0});
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_FALSE(r->passed);
  EXPECT_EQ(r->failing_pixels, 1);
  EXPECT_DOUBLE_EQ(r->failing_percent, 1.0);  // 1 of 100 pixels
  EXPECT_NEAR(r->max_abs, 0.1, 1e-6);
  EXPECT_NEAR(r->mean_abs, 0.1 / 300.0, 1e-8);
}

TEST(ImageCompareTest, FailingPixelsWithinBudgetPass) {
  const Image a = test::constant_image(10, 10, 3, 0.5f);
  Image b = a;
  b.at(3, 7, 1) += 0.1f;
  Result<CompareResult> r = compare_images(a, b, CompareOptions{.fail_threshold = 0.05f, .fail_percent = 1.5});
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_TRUE(r->passed);
  EXPECT_EQ(r->failing_pixels, 1);
}

TEST(ImageCompareTest, DifferenceAtThresholdDoesNotFail) {
  const Image a = test::constant_image(4, 4, 1, 0.0f);
  const Image b = test::constant_image(4, 4, 1, 0.25f);  // exactly representable
  Result<CompareResult> r = compare_images(a, b, CompareOptions{.fail_threshold = 0.25f});
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(r->passed) << "fails only if MORE than the threshold";
}

TEST(ImageCompareTest, SizeMismatchIsAnErrorNamingBothSizes) {
  Result<CompareResult> r =
      compare_images(test::constant_image(4, 3, 3, 0.f), test::constant_image(3, 4, 3, 0.f), CompareOptions{});
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("4x3x3"), std::string::npos) << r.error().message;
  EXPECT_NE(r.error().message.find("3x4x3"), std::string::npos) << r.error().message;
}

TEST(ImageCompareTest, ChannelMismatchIsAnError) {
  Result<CompareResult> r =
      compare_images(test::constant_image(4, 4, 3, 0.f), test::constant_image(4, 4, 4, 0.f), CompareOptions{});
  EXPECT_FALSE(r.ok());
}

TEST(ImageCompareTest, DiffImageIsAmplifiedClampedAndOpaque) {
  const Image a = test::constant_image(2, 1, 4, 0.5f);
  Image b = a;
  b.at(0, 0, 0) += 0.02f;  // x10 -> 0.2
  b.at(1, 0, 2) += 0.5f;   // x10 -> clamped to 1
  Result<CompareResult> r = compare_images(a, b, CompareOptions{});
  ASSERT_TRUE(r.ok());
  const Image& d = r->diff;
  ASSERT_EQ(d.channels, 4);
  EXPECT_NEAR(d.at(0, 0, 0), 0.2f, 1e-5);
  EXPECT_EQ(d.at(0, 0, 1), 0.0f);
  EXPECT_EQ(d.at(1, 0, 2), 1.0f);
  EXPECT_EQ(d.at(0, 0, 3), 1.0f);  // alpha opaque so viewers show the diff
  EXPECT_EQ(d.at(1, 0, 3), 1.0f);
}

TEST(ImageCompareTest, NanOnOneSideFailsAndOnBothSidesMatches) {
  Image a = test::constant_image(2, 1, 1, 0.0f);
  Image b = a;
  a.pixels = {NAN, NAN};
  b.pixels = {NAN, 0.0f};
  Result<CompareResult> r = compare_images(a, b, CompareOptions{});
  ASSERT_TRUE(r.ok());
  EXPECT_FALSE(r->passed);
  EXPECT_EQ(r->failing_pixels, 1);
}

}  // namespace
}  // namespace ps
