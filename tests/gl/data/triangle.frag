#version 450 core
#include "lib/color.glsl"
#include "lib/color.glsl"

in vec2 v_uv;
uniform float u_gain;
layout(location = 0) out vec4 o_color;

void main() { o_color = triangle_color(v_uv) * u_gain; }
