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
  // Crossing diagram (fourd): drawn nearer the eye along the line of sight by u_sheet.w mm per
  // unit of w, so the sheet nearer the 4D eye wins where two cross; the picture does not move
  // and the shading keeps the true position.
  vec3 drawn = a_position;
  if (u_sheet.w > 0.0) {
    vec3 toward_eye = u_eye.w > 0.5 ? normalize(u_eye.xyz - a_position) : -u_eye.xyz;
    drawn += toward_eye * (u_sheet.w * a_w4);
  }
  gl_Position = u_view_proj * vec4(drawn, 1.0);
}
