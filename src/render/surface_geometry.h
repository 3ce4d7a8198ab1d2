// One surface of the scene as the renderer draws it: its mesh on the GPU, its world bounds (the
// plan's input) and, for a surface embedded in 4D, its vertices' w (to find the probe's sheet
// without haptics). Built once per renderer; a deformable surface's mesh is the subdivided one its
// world::DeformableSurfaces holds (stepped by the session, not here), uploaded dynamic.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "core/result.h"
#include "passes/gpu_mesh.h"
#include "render/plan.h"
#include "scene/scene.h"
#include "world/deformable_surfaces.h"

namespace ps {

struct SurfaceGeometry {
  GpuMesh mesh;
  Aabb bounds;  // world mm
  std::vector<glm::vec3> sheet_positions;     // a surface embedded in 4D: its vertices, triangles
  std::vector<std::uint32_t> sheet_indices;   // and the vertices' w
  std::vector<float> w4;                      // (all empty for other surfaces)
  float w_min = 0.0f, w_max = 0.0f;
  // The w of the surface point nearest `probe_mm` (its triangle's nearest corner's): the sheet a
  // probe the haptic side holds on none (hovering, or `render`) casts its shadow on. `fallback`
  // when there is none (no triangles, a NaN probe).
  double nearest_w(const glm::dvec3& probe_mm, double fallback) const;
};

// Surface `index` of a scene (Surface::visual_stretch applied); a deformable one is drawn with its
// mesh in `deformables` as it stands now. Needs a current GL context; a mesh file that cannot be
// read, or a deformable surface `deformables` does not hold, is an error.
Result<SurfaceGeometry> make_surface_geometry(const Surface& s, int index, const world::DeformableSurfaces* deformables);

// The surfaces' bounds, in order (the plan's input).
std::vector<Aabb> bounds_of(std::span<const SurfaceGeometry> surfaces);

}  // namespace ps
