// The probe's ordinary cast shadow (render.cast_shadow, docs/scene-format.md), in double
// precision: the CPU twin of glsl/lib/cast_shadow.glsl. One directional light ([light]
// direction: the direction the light travels) and the probe's bounding sphere (a sphere probe's
// own; a capsule's or mesh probe's bounding sphere, which shadows a little more than the shape):
//   - a receiver point x is in shadow where the ray x + t L, L = -direction, t >= 0, meets the
//     sphere: its distance rho from the sphere's centre line through x is below the radius and
//     the centre lies toward the light (or x is inside the sphere);
//   - coverage: that edge filtered over one pixel, (radius - rho) / edge_mm + 0.5 clamped to
//     [0, 1], `edge_mm` the pixel's largest extent across the light (the plane normal to L), as
//     the bodies' shadows filter their disc (reference/body_shadow.h);
//   - in shadow the point keeps its ambient light only: the lit term of surface.frag's shading,
//     albedo x colour x (ambient + (1 - ambient) x lambert), loses its Lambert part, so the
//     lit factor is ambient + (1 - ambient) x lambert x (1 - coverage). Colour only.
#pragma once

#include <glm/glm.hpp>

#include "reference/body_shadow.h"

namespace ps {

// Share in [0, 1] of the pixel at `x` that the sphere hides from the light travelling along
// `light_dir` (need not be unit).
double cast_shadow_coverage(const SphereCaster& probe, const glm::dvec3& x, const glm::dvec3& light_dir,
                            double edge_mm);

// surface.frag's light factor (ambient + (1 - ambient) lambert) with the lit part removed in
// `coverage` of the pixel. lambert = max(n . -L, 0).
double cast_shadow_light(double ambient, double lambert, double coverage);

// Where the sphere's centre, projected along the light, lands on the plane through `plane_point`
// with normal `n`: the centre of its shadow there (assumes the light is not parallel to the
// plane). Displaced from the foot (the centre's foot along n) by height x the light's slant.
glm::dvec3 cast_shadow_centre(const glm::dvec3& centre, const glm::dvec3& light_dir, const glm::dvec3& plane_point,
                              const glm::dvec3& n);

// The pixel's largest extent (mm) across `dir` (projected onto the plane normal to it), from its
// two screen-space steps dx, dy on the surface: what the shader's dFdx/dFdy give.
double extent_across(const glm::dvec3& dx, const glm::dvec3& dy, const glm::dvec3& dir);

}  // namespace ps
