// ImageIoTest: PNG/EXR round trips, atomic replacement, directory creation and error messages.
// No GL context needed.
#include <cmath>
#include <filesystem>
#include <vector>

#include <gtest/gtest.h>

#include "image/image.h"
#include "image_test_util.h"

namespace ps {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> list_dir(const fs::path& dir) {
  std::vector<fs::path> entries;
  for (const auto& entry : fs::directory_iterator(dir)) entries.push_back(entry.path().filename());
  return entries;
}

TEST(ImageIoTest, PngRoundTripQuantizesWithinHalfStep) {
  const fs::path path = test::scratch_dir() / "gradient.png";
  const Image original = test::gradient_image(17, 9, 4);  // odd, non-square: catches stride bugs
  ASSERT_TRUE(write_image(path.string(), original).ok());
  Result<Image> back = read_image(path.string());
  ASSERT_TRUE(back.ok()) << back.error().message;
  ASSERT_EQ(back->width, 17);
  ASSERT_EQ(back->height, 9);
  ASSERT_EQ(back->channels, 4);
  for (size_t i = 0; i < original.pixels.size(); ++i) {
    // Rounding to nearest 8-bit step: at most half a step off (+ float slack).
    EXPECT_NEAR(back->pixels[i], original.pixels[i], 0.5 / 255.0 + 1e-6) << "index " << i;
  }
}

TEST(ImageIoTest, PngClampsOutOfRangeValues) {
  const fs::path path = test::scratch_dir() / "clamp.png";
  Image image = test::constant_image(2, 1, 3, 0.0f);
  image.pixels = {-1.0f, 2.0f, NAN, 0.5f, 1.0f, 0.0f};
  ASSERT_TRUE(write_image(path.string(), image).ok());
  Result<Image> back = read_image(path.string());
  ASSERT_TRUE(back.ok()) << back.error().message;
  const std::vector<float> expected = {0.0f, 1.0f, 0.0f, 128.0f / 255.0f, 1.0f, 0.0f};
  for (size_t i = 0; i < expected.size(); ++i) EXPECT_FLOAT_EQ(back->pixels[i], expected[i]) << i;
}

TEST(ImageIoTest, ExrRoundTripIsExactFloat) {
  const fs::path path = test::scratch_dir() / "values.exr";
  Image image = test::gradient_image(5, 3, 4);
  // Values half precision would round or overflow (65504 max): the file must be 32-bit float.
  image.pixels[0] = 1e-7f;
  image.pixels[1] = 3.14159274f;
  image.pixels[2] = 123456.789f;
  image.pixels[3] = -0.3333333f;
  ASSERT_TRUE(write_image(path.string(), image).ok());
  Result<Image> back = read_image(path.string());
  ASSERT_TRUE(back.ok()) << back.error().message;
  ASSERT_EQ(back->channels, 4);
  EXPECT_EQ(back->pixels, image.pixels);
}

TEST(ImageIoTest, ReplacingAFileIsAtomicAndLeavesNoTempFile) {
  const fs::path dir = test::scratch_dir();
  const fs::path path = dir / "out.png";
  ASSERT_TRUE(write_image(path.string(), test::constant_image(4, 4, 3, 0.0f)).ok());
  ASSERT_TRUE(write_image(path.string(), test::constant_image(4, 4, 3, 1.0f)).ok());
  EXPECT_EQ(list_dir(dir), std::vector<fs::path>{"out.png"});
  Result<Image> back = read_image(path.string());
  ASSERT_TRUE(back.ok()) << back.error().message;
  for (float v : back->pixels) EXPECT_EQ(v, 1.0f);
}

TEST(ImageIoTest, WriteCreatesOnlyAMissingLastDirectory) {
  const fs::path dir = test::scratch_dir();
  ASSERT_TRUE(write_image((dir / "a" / "c.exr").string(), test::constant_image(3, 2, 1, 0.25f)).ok());
  EXPECT_TRUE(fs::exists(dir / "a" / "c.exr"));
  // Two missing levels: a typo in a parent, never a mkdir -p.
  Status deep = write_image((dir / "x" / "y" / "c.png").string(), test::constant_image(3, 2, 1, 0.25f));
  ASSERT_FALSE(deep.ok());
  EXPECT_NE(deep.error().message.find((dir / "x").string() + " does not exist"), std::string::npos)
      << deep.error().message;
  EXPECT_FALSE(fs::exists(dir / "x"));
}

TEST(ImageIoTest, ReadMissingFileNamesThePath) {
  const fs::path path = test::scratch_dir() / "does_not_exist.png";
  Result<Image> image = read_image(path.string());
  ASSERT_FALSE(image.ok());
  EXPECT_NE(image.error().message.find(path.string() + ": cannot read image: "), std::string::npos)
      << image.error().message;
  EXPECT_EQ(image.error().message.find('\n'), std::string::npos) << "errors are one line";
}

TEST(ImageIoTest, WriteRefusesAbsurdSizes) {
  const fs::path dir = test::scratch_dir();
  Image zero = test::constant_image(1, 1, 3, 0.0f);
  zero.width = 0;
  Status s = write_image((dir / "zero.png").string(), zero);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().message.find("zero.png"), std::string::npos) << s.error().message;
  Image huge{20000, 1, 3, {}};  // refused before any allocation or file is made
  EXPECT_FALSE(write_image((dir / "huge.png").string(), huge).ok());
  EXPECT_TRUE(list_dir(dir).empty());
}

TEST(ImageIoTest, WriteUnknownFormatFailsCleanly) {
  const fs::path dir = test::scratch_dir();
  Status s = write_image((dir / "image.notaformat").string(), test::constant_image(2, 2, 3, 0.5f));
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().message.find("image.notaformat"), std::string::npos) << s.error().message;
  EXPECT_TRUE(list_dir(dir).empty()) << "no temp file may remain";
}

}  // namespace
}  // namespace ps
