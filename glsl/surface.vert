#version 450 core
// Surface pass, vertex stage: world-space position and normal to the fragment stage.
#include "lib/surface_block.glsl"

layout(location = 0) in vec3 a_position;  // world space, mm
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_color;  // multiplies the albedo (white unless the mesh has colours)

layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
layout(location = 2) out vec3 v_color;

void main() {
  v_world = a_position;
  v_normal = a_normal;
  v_color = a_color;
  gl_Position = u_view_proj * vec4(a_position, 1.0);
}
