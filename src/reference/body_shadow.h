// The pseudo-shadows of the scene's bodies (docs/haptics.md, "Bodies"), in double precision:
// the CPU twin of glsl/lib/body_shadow.glsl. A body is a sphere, so its shadow on a receiver is
// analytic: no depth map, no texture, colour only.
//   - d: the sphere's lowest height above the fragment along the reference normal n (the
//     probe's own distance, thesis §4.3.2), d <= 0 where the sphere reaches through it;
//   - darkening: coverage x the receiving material's intensity curve at d;
//   - the shadowed disc, radius R around the sphere's foot on the plane: the part of the
//     sphere's footprint that lies nearer than the influence distance and not wholly below the
//     fragment (a body below a surface is hidden by it, it does not shadow it);
//   - coverage: the disc's edge filtered over one pixel (`edge_mm`: the pixel's largest extent
//     on the plane), so the border is antialiased and a disc shrinking to nothing fades out.
// Several casters (the probe, the bodies) combine multiplicatively, 1 - prod(1 - D_i): each
// only removes light, none can lighten what another darkened (thesis §4.2).
#pragma once

#include <span>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace ps {

struct SphereCaster {
  glm::dvec3 centre{0.0};
  double radius_mm = 0.0;
};

// Radius (mm) of the disc around the sphere's foot on the plane through `x` that the sphere
// shadows; 0 when none (beyond the influence distance, or wholly below x). `height_mm` is the
// sphere centre's height above x along n.
double body_shadow_radius_mm(double height_mm, double radius_mm, double influence_mm);

// One body's darkening in [0, 1] at the receiver point `x` (normal of the reference plane `n`).
double body_shadow_darkening(const Material& receiver, const SphereCaster& body, const glm::dvec3& x,
                             const glm::dvec3& n, double edge_mm);

// All bodies at `x`: 1 - prod(1 - D_i).
double body_shadows_darkening(const Material& receiver, std::span<const SphereCaster> bodies,
                              const glm::dvec3& x, const glm::dvec3& n, double edge_mm);

// Two darkenings combined as independent absorbers: 1 - (1 - a)(1 - b) >= max(a, b).
inline double combine_darkening(double a, double b) { return 1.0 - (1.0 - a) * (1.0 - b); }

}  // namespace ps
