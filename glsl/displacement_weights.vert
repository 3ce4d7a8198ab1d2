#version 450 core
// One triangle covering the whole target: the displacement weights pass (the padded
// displacement target) and the fragment path's row reductions (*_rows.frag, one texel per row).
void main() {
  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
