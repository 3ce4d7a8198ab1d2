// The render thread's local model of the floor for the plane-model tests: the plane z = 0.
#pragma once

#include "haptics/force_model.h"

namespace ps::test {

inline SurfaceModel floor_model(double probe_radius_mm = 8.0) {
  SurfaceModel m;
  m.valid = true;
  m.normal = {0, 0, 1};
  m.point_mm = {0, 0, 0};
  m.probe_radius_mm = probe_radius_mm;
  return m;
}

}  // namespace ps::test
