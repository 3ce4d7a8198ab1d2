#version 450 core
// Probe depth pass, mesh variant: orthographic projection of the probe mesh onto the
// reference plane window; the depth test keeps the lowest height per texel.
#include "lib/probe_depth_block.glsl"

layout(location = 0) in vec3 a_position;  // model space

layout(location = 0) out float v_height;

void main() {
  vec3 w = (u_model * vec4(a_position, 1.0)).xyz;
  vec2 uv = vec2(dot(w, u_ref_t.xyz), dot(w, u_ref_b.xyz));
  float h = dot(w, u_ref_n.xyz);
  v_height = h;
  float z = (h - u_height_range.x) / max(u_height_range.y - u_height_range.x, 1e-6) * 2.0 - 1.0;
  gl_Position = vec4((uv - u_window.xy) / u_window.z, z, 1.0);
}
