#version 450 core
// Probe view pass, vertex stage: the probe (displayed proxy) in the camera view. Only drawn when
// the user asks to see the probe; the pseudo-shadow alone is the default display.
#include "lib/probe_view_block.glsl"

layout(location = 0) in vec3 a_position;  // model space, mm
layout(location = 1) in vec3 a_normal;

layout(location = 0) out vec3 v_normal;

void main() {
  v_normal = mat3(u_model) * a_normal;
  gl_Position = u_view_proj * (u_model * vec4(a_position, 1.0));
}
