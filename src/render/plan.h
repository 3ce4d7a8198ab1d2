// The per-frame plan (CPU only, no GL): what this frame needs and what it can skip.
//   - a surface farther from the probe than its material's influence distance gets no
//     pseudo-shadow (PS_SHADOW=0 variant: no depth lookup, no Gabor);
//   - when no surface is within reach, the probe depth pass and the reductions are skipped;
//   - untextured materials (textured = false or zero amplitude) use PS_TEXTURED=0;
//   - inside a shadowed surface the Gabor sum runs only on fragments inside the probe's
//     footprint and onset distance (a branch in glsl/surface.frag), so its cost follows the
//     footprint's pixel count rather than the screen size;
//   - outside the footprint's screen-space bound (shadow_rect) the surface pass draws the plain
//     variant and writes no AOV, and the reductions read nothing there: every pixel outside it
//     holds the "no probe" values, which carry no information.
#pragma once

#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "passes/pixel_rect.h"
#include "passes/probe_depth.h"
#include "reference/basis.h"
#include "reference/body_shadow.h"
#include "reference/probe_geometry.h"
#include "scene/scene.h"

namespace ps {

struct Aabb {
  glm::dvec3 min{0.0}, max{0.0};
};

// What the plan decided for one surface.
struct SurfacePlan {
  bool shadow = false;       // PS_SHADOW: within the material's influence distance
  bool textured = false;     // PS_TEXTURED: shadowed and textured
  double distance_mm = 0.0;  // probe bounds to surface bounds
};

struct FramePlan {
  bool shadow_active = false;           // depth pass + reductions run
  std::vector<SurfacePlan> surfaces;    // index = Scene::surfaces
  DepthWindow window;
  // The pixels (image size, GL window coordinates) that can show a shadowed surface inside the
  // depth-map window: the only ones whose intensity, distance and texture can differ from the
  // "no probe" values (0, NaN, 0). Empty when shadow_active is false.
  PixelRect shadow_rect;
  std::vector<std::string> skipped;     // human-readable, for --stats
};

double distance_sphere_aabb(const BoundingSphere& s, const Aabb& box);

// The bodies whose pseudo-shadow can fall on a surface with these bounds: those nearer than
// the influence distance to the box (a shadowed point lies within that distance of the sphere
// along the normal, so at most that far from it), in order; bodies at non-finite positions are
// left out. The rest cost the surface nothing.
std::vector<SphereCaster> bodies_in_reach(std::span<const SphereCaster> bodies, const Aabb& bounds,
                                          double influence_mm);
// A conservative screen-space bound of the points whose plane coordinates lie inside `window`
// (widened by one texel of a `depth_map_size` map) and whose height along frame.n lies in
// [height_lo, height_hi]: the bounding rectangle of that box's eight corners in pixels, plus
// two pixels of margin (float rounding of the shader's world positions), clipped to the
// image. The whole image when a corner is not in front of a perspective camera (the box's
// projection is then unbounded).
PixelRect footprint_screen_rect(const Camera& camera, int width, int height, const PlaneFrame& frame,
                                const DepthWindow& window, int depth_map_size, double height_lo,
                                double height_hi);

// The material draws a Gabor texture at all (textured, some amplitude, some impulses).
bool has_texture(const Material& m);

// `depth_map_size` sets the margin: the window is the probe's bounding disc plus one texel.
// `camera`: the one the frame draws with (the scene's moved by the view, Renderer::camera()).
// `surface_bounds`: index = Scene::surfaces.
FramePlan make_plan(const Scene& scene, const Camera& camera, std::span<const Aabb> surface_bounds,
                    const BoundingSphere& probe, const PlaneFrame& frame, int depth_map_size);
// The scene's own camera.
FramePlan make_plan(const Scene& scene, std::span<const Aabb> surface_bounds,
                    const BoundingSphere& probe, const PlaneFrame& frame, int depth_map_size);

}  // namespace ps
