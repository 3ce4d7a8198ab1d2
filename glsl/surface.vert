#version 450 core
// Surface pass, vertex stage: world-space position and normal to the fragment stage.
#include "lib/surface_block.glsl"

layout(location = 0) in vec3 a_position;  // world space, mm
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_color;  // multiplies the albedo (white unless the mesh has colours)
layout(location = 3) in float a_w4;    // 4D depth w (surfaces embedded in 4D; else 0)

layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
layout(location = 2) out vec3 v_color;
layout(location = 3) out float v_w4;

void main() {
  v_world = a_position;
  v_normal = a_normal;
  v_color = a_color;
  v_w4 = a_w4;
  gl_Position = u_view_proj * vec4(a_position, 1.0);
}
