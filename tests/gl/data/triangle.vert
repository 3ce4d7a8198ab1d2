#version 450 core
// Full-viewport triangle from gl_VertexID, no vertex buffers needed.
out vec2 v_uv;

void main() {
  const vec2 kCorners[3] = vec2[3](vec2(-0.9, -0.8), vec2(0.8, -0.6), vec2(-0.1, 0.9));
  vec2 p = kCorners[gl_VertexID];
  v_uv = p * 0.5 + 0.5;
  gl_Position = vec4(p, 0.0, 1.0);
}
