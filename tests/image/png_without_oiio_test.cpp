// PngWithoutOiioTest: reading and writing PNG never loads OpenImageIO. Its own executable so no
// other test in the process can have loaded the module first (gtest may run all tests in one
// process). No GL needed.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "image/image.h"
#include "image_test_util.h"

namespace ps {
namespace {

std::string self_maps() {
  std::ifstream maps("/proc/self/maps");
  return std::string((std::istreambuf_iterator<char>(maps)), std::istreambuf_iterator<char>());
}

TEST(PngWithoutOiioTest, PngReadAndWriteNeverMapOpenImageIO) {
  const std::filesystem::path dir = test::scratch_dir();
  for (int channels = 1; channels <= 4; ++channels) {
    const std::string path = (dir / ("c" + std::to_string(channels) + ".png")).string();
    ASSERT_TRUE(write_image(path, test::gradient_image(9, 4, channels)).ok());
    Result<Image> back = read_image(path);
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_EQ(back->channels, channels);
  }
  // Errors on the PNG path stay on it too.
  EXPECT_FALSE(read_image((dir / "missing.png").string()).ok());
  const std::string maps = self_maps();
  EXPECT_EQ(maps.find("libOpenImageIO"), std::string::npos);
  EXPECT_EQ(maps.find("libps_image_oiio"), std::string::npos);
}

}  // namespace
}  // namespace ps
