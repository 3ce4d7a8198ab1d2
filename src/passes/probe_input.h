// The probe as the probe passes (probe_depth, probe_view) take it: a mesh with its model matrix,
// or (mesh == nullptr) the analytic sphere/capsule in world space.
#pragma once

#include <glm/glm.hpp>

#include "passes/gpu_mesh.h"
#include "reference/probe_geometry.h"

namespace ps {

struct ProbeInput {
  const GpuMesh* mesh = nullptr;  // mesh probe, placed by `model`; nullptr: `capsule`
  glm::dmat4 model{1.0};
  CapsuleShape capsule;           // analytic probe (a == b: a sphere), world space
};

}  // namespace ps
