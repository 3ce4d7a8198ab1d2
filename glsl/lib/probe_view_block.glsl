// Uniform contract of the probe view pass; mirrored by ProbeViewBlock in src/passes/probe_view.h.
#pragma once

layout(std140, binding = 0) uniform ProbeViewBlock {
  mat4 u_view_proj;
  mat4 u_model;          // translation (and, for the capsule, none else)
  vec4 u_light_dir;      // xyz: direction the light travels; w: ambient
  vec4 u_light_color;    // rgb; a: output gamma
  vec4 u_probe_color;    // rgb, linear; a: unused
};
