#version 450 core
// Probe view pass, fragment stage: Lambert shading of the probe (or a body, or the faint device
// ghost at u_probe_color.a < 1, blended by the pass) in one colour, drawn
// over the surface pass's colour target with its depth buffer (the probe sinks into surfaces
// exactly where it penetrates them). Writes colour only; the AOVs and reductions never see it.
#include "lib/probe_view_block.glsl"

layout(location = 0) in vec3 v_normal;
layout(location = 0) out vec4 o_color;

void main() {
  vec3 n = normalize(v_normal);  // outward normals of a closed probe: no two-sided flip
  float lambert = max(dot(n, -normalize(u_light_dir.xyz)), 0.0);
  vec3 rgb = u_probe_color.rgb * u_light_color.rgb * (u_light_dir.w + (1.0 - u_light_dir.w) * lambert);
  o_color = vec4(pow(clamp(rgb, 0.0, 1.0), vec3(u_light_color.a)), u_probe_color.a);
}
