// Orthonormal frame of the reference plane (thesis §4.5.2): normal n and tangents t, b.
// (u, v) = (dot(x, t), dot(x, b)) indexes both the probe depth map and the Gabor texture;
// h = dot(x, n) is the height above the plane through the world origin.
#pragma once

#include <cmath>

#include <glm/glm.hpp>

namespace ps {

struct PlaneFrame {
  glm::dvec3 n{0.0, 0.0, 1.0};
  glm::dvec3 t{1.0, 0.0, 0.0};
  glm::dvec3 b{0.0, 1.0, 0.0};
};

// Duff et al. 2017, "Building an Orthonormal Basis, Revisited": continuous except on the
// n.z = -1 seam, no branches on near-parallel axes, exact (1,0,0),(0,1,0) for n = +Z.
inline PlaneFrame make_plane_frame(glm::dvec3 n) {
  n = glm::normalize(n);
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double b = n.x * n.y * a;
  PlaneFrame f;
  f.n = n;
  f.t = glm::dvec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
  f.b = glm::dvec3(b, sign + n.y * n.y * a, -n.y);
  return f;
}

inline glm::dvec3 to_plane(const PlaneFrame& f, const glm::dvec3& x) {
  return {glm::dot(x, f.t), glm::dot(x, f.b), glm::dot(x, f.n)};
}

}  // namespace ps
