// Shared by the triangle fixtures; included twice by triangle.frag to exercise #pragma once.
#pragma once

vec4 triangle_color(vec2 uv) {
  // Gradients so every pixel differs: a backend difference would show up in the bytes.
  return vec4(uv.x, uv.y, 1.0 - uv.x * uv.y, 1.0) * TINT;
}
