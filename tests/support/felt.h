// A haptic scene built from scene TOML text (relative files resolve against the working
// directory): for tests that feel a few shapes without a scene file. Failures are reported as
// test failures where they happen.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "scene/scene_io.h"
#include "world/haptic_scene.h"

namespace ps {

inline std::shared_ptr<const world::HapticScene> felt(const std::string& toml) {
  auto scene = parse_scene(toml, "f.toml", ".", {});
  EXPECT_TRUE(scene) << scene.error().message;
  auto built = world::HapticScene::build(scene.value());
  EXPECT_TRUE(built) << built.error().message;
  return std::make_shared<const world::HapticScene>(std::move(built.value()));
}

}  // namespace ps
