#version 450 core
// The error is not in this file but in the included one.
#include "lib/broken.glsl"

layout(location = 0) out vec4 o_color;

void main() { o_color = vec4(broken_value()); }
