// GoldenLimitsTest: the tolerances in tests/golden/CMakeLists.txt catch a small, sharp change.
// Each golden is copied, 23 of its 16384 pixels are moved by 24 levels (0.14 % of the pixels:
// inside the 0.5 % budget, so only the hard cap can catch it), and `compare` is run with that
// case's limits exactly as run_golden.cmake runs it. Without --hardfail the same change passes,
// which is what the goldens allowed before the cap existed.
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/commands/compare_cmd.h"
#include "image/image.h"
#include "image/image_test_util.h"

namespace ps {
namespace {

namespace fs = std::filesystem;

struct GoldenCase {
  std::string name, fail_percent, hard_fail;
};

// PS_GOLDEN_LIMITS: "name|failpercent|hardfail,..." from tests/golden/CMakeLists.txt.
std::vector<GoldenCase> golden_cases() {
  std::vector<GoldenCase> cases;
  std::stringstream all(PS_GOLDEN_LIMITS);
  for (std::string item; std::getline(all, item, ',');) {
    std::stringstream fields(item);
    GoldenCase c;
    std::getline(fields, c.name, '|');
    std::getline(fields, c.fail_percent, '|');
    std::getline(fields, c.hard_fail, '|');
    cases.push_back(c);
  }
  return cases;
}

// Exit status of `compare ARGS...`; its summary line is echoed so a failure shows the numbers.
int compare(std::vector<std::string> args) {
  const test::CompareRun r = test::run_compare_captured(std::move(args));
  std::printf("%s%s", r.out.c_str(), r.err.c_str());
  return r.code;
}

// 23 pixels spread over the image, channel 0 moved by 24 levels (down where up would clip).
Image perturbed(Image im) {
  constexpr int kPixels = 23, kLevels = 24;
  for (int i = 0; i < kPixels; ++i) {
    const int x = (i * 37 + 11) % im.width, y = (i * 53 + 7) % im.height;
    float& v = im.at(x, y, 0);
    v += (v * 255.0f + kLevels <= 255.0f ? kLevels : -kLevels) / 255.0f;
  }
  return im;
}

TEST(GoldenLimitsTest, TwentyFourLevelsOnTwentyThreePixelsFailEveryGolden) {
  const std::vector<GoldenCase> cases = golden_cases();
  std::size_t goldens = 0;  // every golden image has its case (and so its limits checked)
  for (const auto& e : fs::directory_iterator(fs::path(PS_SOURCE_DIR) / "golden_images"))
    goldens += e.path().extension() == ".png";
  ASSERT_EQ(cases.size(), goldens) << "one case per golden image";
  ASSERT_GE(cases.size(), 18u);
  const fs::path dir = fs::path(PS_BINARY_DIR) / "test_scratch" / "golden_limits";
  fs::create_directories(dir);
  for (const GoldenCase& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string golden = std::string(PS_SOURCE_DIR) + "/golden_images/" + c.name + ".png";
    Result<Image> im = read_image(golden);
    ASSERT_TRUE(im.ok()) << im.error().message;
    const std::string actual = (dir / (c.name + ".perturbed.png")).string();
    ASSERT_TRUE(write_image(actual, perturbed(im.value())).ok());
    const std::vector<std::string> limits = {golden, actual, "--fail", PS_GOLDEN_FAIL, "--failpercent", c.fail_percent};
    std::vector<std::string> capped = limits;
    capped.insert(capped.end(), {"--hardfail", c.hard_fail});
    EXPECT_EQ(compare(limits), 0) << "without the cap the budget hides the change";
    EXPECT_EQ(compare(capped), 1) << "the per-pixel cap must catch it";
    // The cap leaves room for what it is there for: one level on every pixel still passes.
    Image one_level = im.value();
    for (float& v : one_level.pixels) v = v * 255.0f + 1.0f <= 255.0f ? v + 1.0f / 255.0f : v - 1.0f / 255.0f;
    ASSERT_TRUE(write_image(actual, one_level).ok());
    EXPECT_EQ(compare(capped), 0) << "a one-level change everywhere is within the golden limits";
    fs::remove(actual);
  }
}

}  // namespace
}  // namespace ps
