// A shipped scene at a given image size, and bit-for-bit image equality: for the GL tests that
// compare whole frames of the shipped scenes (incremental, adaptive, footprint rectangle).
// Header only: PS_SOURCE_DIR comes from the including test's target.
#pragma once

#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "image/image.h"
#include "scene/scene.h"
#include "scene/scene_io.h"

namespace ps::test {

// scenes/NAME.toml with render.size = [width, height]; an empty scene (and a test failure naming
// why) when it does not load.
inline Scene shipped(const std::string& name, int width, int height) {
  auto s = load_scene(std::string(PS_SOURCE_DIR) + "/scenes/" + name + ".toml",
                      {"render.size=[" + std::to_string(width) + "," + std::to_string(height) + "]"});
  EXPECT_TRUE(s.ok()) << (s.ok() ? "" : s.error().message);
  return s.ok() ? s.value() : Scene{};
}

inline bool same_bits(const Image& a, const Image& b) {
  return a.width == b.width && a.height == b.height && a.channels == b.channels &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

}  // namespace ps::test
