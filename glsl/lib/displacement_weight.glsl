// Pseudo-haptic displacement of one fragment (thesis §4.5.4, step 3g), as (w * disp, w):
//   displacement = resistance * (-d) * normal,  weight = (1 - d)^c,
// the weight rescaled by (1 + max penetration)^-c (in log space) so it lies in (0, 1] and
// cannot overflow; the factor cancels in sum(w * disp) / sum(w). Zero outside the shadow and
// where the probe does not penetrate. Used by displacement_rows.comp (the frame's average) and
// displacement_weights.frag (the `displacement` AOV). Needs lib/reduce_block.glsl (u_params).
#pragma once

vec4 weighted_displacement(sampler2D aov_tex, sampler2D normal_tex, ivec2 p, float max_pen) {
  vec4 aov = texelFetch(aov_tex, p, 0);  // (intensity, d, texture, resistance)
  float pen = -aov.y;
  if (!(aov.x > 0.0 && pen > 0.0)) return vec4(0.0);
  float w = exp(u_params.x * (log(1.0 + min(pen, max_pen)) - log(1.0 + max_pen)));
  vec3 disp = aov.w * pen * texelFetch(normal_tex, p, 0).xyz;
  return vec4(w * disp, w);
}
