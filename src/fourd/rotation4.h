// Rotations of R^4 in its six coordinate planes and the 4D -> 3D projection (docs/fourd.md).
// Double precision, no allocation. Convention: a point is a column glm::dvec4 (x, y, z, w);
// the 4D eye looks along -w, so w is the "4D depth" coordinate (larger w = nearer the eye).
#pragma once

#include <array>

#include <glm/glm.hpp>

#include "fourd/spec.h"

namespace ps::fourd {

// Rotation by `radians` in the plane of axes a < b (x = 0 ... w = 3): e_a turns toward e_b.
glm::dmat4 plane_rotation(int a, int b, double radians);
// The six plane rotations of `degrees` (kRotationPlanes order), the xy one applied first.
glm::dmat4 rotation_from_deg(const std::array<double, 6>& degrees);

struct Projected {
  glm::dvec3 p3{0.0};  // the 3D image (4D units)
  double w = 0.0;      // 4D depth: the rotated point's w coordinate
};

// Perspective: p3 = xyz * E / (E - w), the eye at (0, 0, 0, E) and the image space w = 0;
// orthographic: p3 = xyz. Perspective needs w < E (asserted: the caller checks the surface).
Projected project(const glm::dvec4& p, Projection4 kind, double eye_distance);
// The inverse for a known depth: the 4D point whose image is p3 at depth w.
glm::dvec4 unproject(const glm::dvec3& p3, double w, Projection4 kind, double eye_distance);

}  // namespace ps::fourd
