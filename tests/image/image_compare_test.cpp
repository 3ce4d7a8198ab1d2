// ImageCompareTest: thresholds, failing-pixel budget, size mismatch, diff image. No GL needed.
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

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

// 8-bit files compare in whole levels. Written and read back through PNG so the values are what
// read_image makes of real 8-bit files (k * (1/255.f)), where float rounding alone used to fail
// 7 of the 255 one-level pairs.
class EightBitCompareTest : public ::testing::Test {
 protected:
  // A 1-row gray PNG whose pixel x holds level first + x (x < count), read back.
  Image levels_png(const char* name, int first, int count) {
    Image im = test::constant_image(count, 1, 1, 0.0f);
    for (int x = 0; x < count; ++x) im.at(x, 0, 0) = static_cast<float>(first + x) / 255.0f;
    const std::string path = (dir_ / name).string();
    EXPECT_TRUE(write_image(path, im).ok());
    Result<Image> back = read_image(path);
    EXPECT_TRUE(back.ok()) << back.error().message;
    // Independent check that the file holds the intended levels (0.5: halfway to a neighbour).
    for (int x = 0; x < count; ++x) EXPECT_NEAR(back->at(x, 0, 0) * 255.0f, first + x, 0.5f) << x;
    EXPECT_EQ(back->file_bits, 8);
    return back.value();
  }
  std::filesystem::path dir_ = test::scratch_dir();
};

TEST_F(EightBitCompareTest, EveryOneLevelPairPassesAtTheDefault) {
  const Image a = levels_png("a.png", 0, 255);  // v = 0..254
  const Image b = levels_png("b.png", 1, 255);  // v + 1
  Result<CompareResult> r = compare_images(a, b, CompareOptions{});
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(r->in_levels);
  EXPECT_EQ(r->failing_pixels, 0);
  EXPECT_EQ(r->max_levels, 1);
  EXPECT_TRUE(r->passed);
  // The same values compared as floats fail exactly the pairs float rounding of k/255 puts
  // beyond 1/255 (found by hand: v = 2, 5, 11, 23, 47, 95, 191) - the reason levels exist.
  Image fa = a, fb = b;
  fa.file_bits = fb.file_bits = 0;
  Result<CompareResult> f = compare_images(fa, fb, CompareOptions{});
  ASSERT_TRUE(f.ok());
  std::vector<int> failing;
  for (int v = 0; v < 255; ++v) {
    Result<CompareResult> one = compare_images(test::constant_image(1, 1, 1, fa.at(v, 0, 0)),
                                               test::constant_image(1, 1, 1, fb.at(v, 0, 0)), CompareOptions{});
    if (!one->passed) failing.push_back(v);
  }
  EXPECT_EQ(failing, (std::vector<int>{2, 5, 11, 23, 47, 95, 191}));
  EXPECT_EQ(f->failing_pixels, 7);
}

TEST_F(EightBitCompareTest, EveryTwoLevelPairFailsAtTheDefault) {
  const Image a = levels_png("a.png", 0, 254);  // v = 0..253
  const Image b = levels_png("b.png", 2, 254);  // v + 2
  Result<CompareResult> r = compare_images(a, b, CompareOptions{});
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r->failing_pixels, 254);
  EXPECT_EQ(r->max_levels, 2);
  EXPECT_FALSE(r->passed);
}

TEST_F(EightBitCompareTest, ThresholdsRoundToTheNearestLevel) {
  const Image a = levels_png("a.png", 0, 254);
  const Image one = levels_png("one.png", 1, 254);
  const Image two = levels_png("two.png", 2, 254);
  auto passes = [](const Image& x, const Image& y, float t) {
    return compare_images(x, y, CompareOptions{.fail_threshold = t})->passed;
  };
  EXPECT_FALSE(passes(a, one, 0.0f));     // 0 levels
  EXPECT_FALSE(passes(a, one, 0.0019f));  // 0.48 -> 0 levels
  EXPECT_TRUE(passes(a, one, 0.002f));    // 0.51 -> 1 level
  EXPECT_TRUE(passes(a, one, 0.004f));    // 1.02 -> 1 level
  EXPECT_FALSE(passes(a, two, 0.004f));
  EXPECT_TRUE(passes(a, two, 0.0078f));   // 1.99 -> 2 levels
}

TEST_F(EightBitCompareTest, HardFailCapsEveryPixelWhateverTheBudget) {
  // The golden case it exists for: 23 of 16384 pixels (0.14 %) changed by 24 levels pass a
  // 0.5 % budget at 1 level, and must not.
  Image a = test::constant_image(128, 128, 3, 100.0f / 255.0f);
  Image b = a;
  for (int i = 0; i < 23; ++i) b.at(i * 5, i * 3, 1) = 124.0f / 255.0f;
  const std::string pa = (dir_ / "a.png").string(), pb = (dir_ / "b.png").string();
  ASSERT_TRUE(write_image(pa, a).ok());
  ASSERT_TRUE(write_image(pb, b).ok());
  const Image fa = read_image(pa).value(), fb = read_image(pb).value();
  CompareOptions budget{.fail_threshold = 0.004f, .fail_percent = 0.5};
  Result<CompareResult> r = compare_images(fa, fb, budget);
  EXPECT_TRUE(r->passed) << "without a cap the budget hides the change";
  EXPECT_EQ(r->failing_pixels, 23);
  budget.hard_fail_threshold = 4.0f / 255.0f;
  r = compare_images(fa, fb, budget);
  EXPECT_FALSE(r->passed);
  EXPECT_EQ(r->hard_failing_pixels, 23);
  budget.hard_fail_threshold = 24.0f / 255.0f;  // a difference AT the cap does not fail
  EXPECT_TRUE(compare_images(fa, fb, budget)->passed);
}

TEST(ImageCompareTest, HardFailOnFloatImages) {
  const Image a = test::constant_image(10, 10, 1, 0.5f);
  Image b = a;
  b.at(1, 1, 0) = 0.75f;  // exactly representable: a 0.25 difference
  CompareOptions o{.fail_threshold = 0.0f, .fail_percent = 100.0, .hard_fail_threshold = 0.25f};
  EXPECT_TRUE(compare_images(a, b, o)->passed);
  o.hard_fail_threshold = 0.2f;
  Result<CompareResult> r = compare_images(a, b, o);
  EXPECT_FALSE(r->passed);
  EXPECT_FALSE(r->in_levels);
  EXPECT_EQ(r->hard_failing_pixels, 1);
}

}  // namespace
}  // namespace ps
