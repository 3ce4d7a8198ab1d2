// Uniform contract of the probe depth pass; mirrored by ProbeDepthBlock in src/passes/probe_depth.h.
#pragma once

layout(std140, binding = 0) uniform ProbeDepthBlock {
  mat4 u_model;          // mesh probe: model -> world
  vec4 u_ref_n;          // reference plane normal
  vec4 u_ref_t;          // u axis
  vec4 u_ref_b;          // v axis
  vec4 u_window;         // xy: window centre (u, v) mm; z: half size mm; w: texels per side
  vec4 u_cap_a;          // analytic probe: xyz capsule end a (plane coords u, v, h); w radius mm
  vec4 u_cap_b;          // xyz capsule end b (plane coords)
  vec4 u_height_range;   // mesh probe: x lowest, y highest plane height for the depth buffer
};
