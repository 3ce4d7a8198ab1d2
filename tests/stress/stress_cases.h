// The cases of the numerical stress suite: a base scene and one edit per case.
#pragma once

#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace ps::test {

struct StressCase {
  std::string name;
  std::function<void(Scene&)> edit;
  int frames = 2;
  // The probe penetrates: the push along the reference normal must be a real one (> half of
  // resistance x max penetration), not a non-finite result silently zeroed.
  bool expect_push = false;
};

// gtest prints a parameter with this (found by ADL) instead of its bytes.
inline void PrintTo(const StressCase& c, std::ostream* os) { *os << c.name; }

// 32^2 orthographic view of a textured plane, sphere probe r = 8 mm sunk 1 mm into it.
Scene stress_base_scene();
const std::vector<StressCase>& stress_cases();

}  // namespace ps::test
