// The per-fragment and per-frame formulas of the method, in double precision: pseudo-shadow
// intensity (thesis §4.3.2), speed modulation of the texture amplitude (§4.3.1, §4.5.3) and
// the pseudo-haptic displacement weight (§4.5.4). The renderer uses speed_gain() to set the
// shader's per-frame uniform; the others are the CPU twins of glsl/lib/pseudo_shadow.glsl.
#pragma once

#include <glm/glm.hpp>

#include "reference/basis.h"
#include "scene/scene.h"

namespace ps {

// The material's distance -> intensity curve in [0, 1] on its own, for d >= 0 (no contact jump, no
// influence cut): its intensity_lut if it has one (scene/lut.h), else floor + scale / (d + offset).
double intensity_curve(const Material& m, double distance_mm);

// 1 where d <= 0 (contact), floor + scale / (d + offset) where 0 < d < influence, 0 beyond.
double shadow_intensity(const Material& m, double distance_mm);

// Darkening in [0, 1] (the share of the surface's light the pseudo-shadow removes) with the
// texture on; twin of pseudo_shadow_darkening() in glsl/lib/pseudo_shadow.glsl:
//   I + A * clamp(s, -1, 1),  A = gain * min(I - I(onset), 1 - I) for 0 < d < onset, 0 beyond;
// at contact the mean is 1 - gain * h and A = gain * h, h = (1 - I(0+)) / 2. `s` is the
// texture value over the contrast (sigmas / sigmas), `coverage` the footprint's share.
double pseudo_shadow_darkening(const Material& m, double distance_mm, double coverage,
                               double gain, double s);

// Distance of the vibration frequency range [s/lambda_max, s/lambda_min] from the peak (Hz):
// 0 when the range contains the peak.
double frequency_gap_hz(double speed_mm_s, double lambda_min_mm, double lambda_max_mm,
                        double peak_hz);

// exp(-(gap / bandwidth)^2) for one speed, or the material's speed_gain_lut at that speed.
double amplitude_gain(const Material& m, double speed_mm_s);

// Blend (§4.5.3) of the gain for the speed along the mean texture direction and the gain for
// the in-plane speed, weighted by anisotropy |theta_max - theta_min| / pi (clamped to [0,1]).
// `velocity` is the probe velocity (mm/s) in world space; it is projected on the plane `f`.
double speed_gain(const Material& m, const PlaneFrame& f, const glm::dvec3& velocity);

// Thesis weight (1 - d)^c, rescaled by (1 + max_penetration)^-c so it never overflows:
// exp(c * (log1p(-d) - log1p(max_pen))) in (0, 1] for d in [-max_pen, 0]; 0 where d > 0.
double displacement_weight(double distance_mm, double exponent_c, double max_penetration_mm);

}  // namespace ps
