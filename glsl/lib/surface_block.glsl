// Uniform contract of the surface pass. Mirrored by SurfaceBlock in src/passes/surface.h
// (std140: only vec4/mat4/uvec4 members so C++ and GLSL agree on every offset).
#pragma once

#include "gabor_block.glsl"

const int kMaxBodyCasters = 4;  // SurfaceBlock::body_spheres (= kMaxSceneBodies)

layout(std140, binding = 0) uniform SurfaceBlock {
  mat4 u_view_proj;
  vec4 u_light_dir;      // xyz: direction the light travels (unit); w: ambient
  vec4 u_light_color;    // rgb; a: output gamma (1/2.2 encodes for PNG)
  vec4 u_ref_n;          // reference plane normal; w: 1 = d along the surface's own normal (else the reference's)
  vec4 u_ref_t;          // reference plane tangent (u axis); w: lowest height of the probe's bounds along u_ref_n
  vec4 u_ref_b;          // reference plane bitangent (v axis); w: highest height of the probe's bounds
  vec4 u_window;         // xy: depth-map window centre (u, v) mm; z: half size mm; w: depth map texels
  vec4 u_albedo;         // rgb albedo; a: 1 when an albedo texture is bound
  vec4 u_albedo_scale;   // x: world size of one albedo texture repeat, mm; yz: world (x, y) of a repeat's corner; w: unused
  vec4 u_intensity;      // x floor, y scale, z offset mm, w influence distance mm
  vec4 u_modulation;     // x speed gain [0,1], y onset distance mm, z resistance, w contrast (sigmas)
  GaborBlock u_gabor;    // the material's texture (lib/gabor_block.glsl)
  vec4 u_body_spheres[kMaxBodyCasters];  // bodies casting on this surface: centre mm, radius mm
  uvec4 u_body_count;    // x: how many of u_body_spheres are set (lib/body_shadow.glsl)
  vec4 u_sheet;          // x: 1 = pseudo-shadow on one sheet of a surface embedded in 4D only;
                         // y: that sheet's w; z: the band of w around y that is that sheet;
                         // w: crossing diagram, mm nearer the eye per unit of w (0: off)
  vec4 u_cutaway;        // xyz: the probe's centre mm; w: cutaway radius mm (0: off), fourd only
  vec4 u_probe_a;        // sphere/capsule probe, plane coordinates (u, v, height) mm: end a; w: radius mm
  vec4 u_probe_b;        // xyz: end b (= a for a sphere); w: 1 = surface_normal distances in closed
                         // form against this capsule, 0 = marched through the depth map (mesh probe)
  vec4 u_eye;            // xyz: the camera position mm (perspective) or its view direction
                         // (orthographic); w: 1 perspective, 0 orthographic
  vec4 u_cast_sphere;    // render.cast_shadow: the probe's bounding sphere, world centre mm, radius
                         // mm in w (0: no cast shadow; lib/cast_shadow.glsl)
  vec4 u_feedback;       // x: 1 = the probe's pseudo-shadow is composited into the colour (render.pseudo_shadow)
};
