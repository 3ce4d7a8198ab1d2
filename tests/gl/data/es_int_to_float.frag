#version 450 core
// Legal GLSL 4.50 (an int converts to float implicitly), not GLSL ES 3.00: ps_glslcheck --es
// must reject it with file:line, ps_glslcheck without --es must pass it.
layout(location = 0) out vec4 o_color;
void main() {
  float half_value = 1 / 2.0;
  o_color = vec4(half_value);
}
