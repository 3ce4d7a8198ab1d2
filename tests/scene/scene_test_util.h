// Helpers shared by the scene tests.
#pragma once

#include <string>
#include <vector>

#include "scene/scene_io.h"

namespace ps::test {

inline std::string scenes_dir() { return std::string(PS_SOURCE_DIR) + "/scenes"; }

// A valid minimal scene; tests append or substitute lines to make it wrong.
inline const char* kMinimalScene = R"(# line 1
[materials.wood]
lambda_min = 0.1

[[surfaces]]
material = "wood"
)";

inline Result<Scene> parse(const std::string& text, const std::vector<std::string>& sets = {}) {
  return parse_scene(text, "s.toml", scenes_dir(), sets);
}

// The error message of a parse that must fail ("<ok>" when it did not fail).
inline std::string error_of(const std::string& text, const std::vector<std::string>& sets = {}) {
  Result<Scene> scene = parse(text, sets);
  return scene ? std::string("<ok>") : scene.error().message;
}

}  // namespace ps::test
