// Helpers shared by the image tests: a per-test scratch directory and small synthetic images.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/commands/compare_cmd.h"
#include "image/image.h"

namespace ps::test {

// A fresh directory under the build tree (or /tmp), named after the running test.
inline std::filesystem::path scratch_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::filesystem::path dir = std::filesystem::path(PS_BINARY_DIR) / "test_scratch" / "image" /
                              (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// Deterministic gradient with values spread over [0,1] (and exactly representable in float).
inline Image gradient_image(int width, int height, int channels) {
  Image image{width, height, channels, {}};
  image.pixels.resize(static_cast<size_t>(width) * height * channels);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < channels; ++c)
        image.at(x, y, c) = static_cast<float>((x * 7 + y * 13 + c * 29) % 101) / 100.0f;
  return image;
}

inline Image constant_image(int width, int height, int channels, float value) {
  Image image{width, height, channels, {}};
  image.pixels.assign(static_cast<size_t>(width) * height * channels, value);
  return image;
}

// `pseudoshadow compare ARGS...` run in-process: exit status, stdout and stderr.
struct CompareRun {
  int code = -1;
  std::string out, err;
};
inline CompareRun run_compare_captured(std::vector<std::string> args) {
  args.insert(args.begin(), "compare");
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  ::testing::internal::CaptureStdout();
  ::testing::internal::CaptureStderr();
  CompareRun r;
  r.code = run_compare(static_cast<int>(args.size()), argv.data());
  r.out = ::testing::internal::GetCapturedStdout();
  r.err = ::testing::internal::GetCapturedStderr();
  return r;
}

}  // namespace ps::test
