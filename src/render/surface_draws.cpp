#include "render/surface_draws.h"

#include "render/renderer.h"
#include "scene/camera.h"

namespace ps {

SurfaceFrame surface_frame(const RenderSettings& rs, const Camera& camera, const Light& light, const PlaneFrame& frame,
                           const FramePlan& plan, const BoundingSphere& probe, const Probe& p,
                           const RendererOptions& options) {
  SurfaceFrame fr;
  fr.view_proj = view_projection(camera, static_cast<double>(rs.width) / rs.height);
  fr.plane = frame;
  fr.window_center_uv = plan.window.center_uv;
  fr.window_half_mm = plan.window.half_size_mm;
  fr.depth_map_size = rs.depth_map_size;
  fr.light = &light;
  fr.contrast_sigmas = options.contrast_sigmas;
  fr.surface_normal_distance = rs.shadow_distance == ShadowDistance::kSurfaceNormal;
  fr.probe_height_lo_mm = glm::dot(probe.center, frame.n) - probe.radius;
  fr.probe_height_hi_mm = glm::dot(probe.center, frame.n) + probe.radius;
  if (p.shape != ProbeShape::kMesh && options.closed_form_normal_distance) fr.probe_capsule = capsule_of(p);
  fr.pseudo_shadow_color = rs.pseudo_shadow;
  // The bounding sphere for every shape: exact for the sphere probe (the experiment's), a little
  // larger than a capsule or mesh (their shadow is a disc's, not their outline's).
  if (rs.cast_shadow) fr.cast_caster = SphereCaster{probe.center, probe.radius};
  return fr;
}

SurfaceDraw material_draw(const MaterialGpu& ms, bool filter_negligible) {
  SurfaceDraw d;
  d.stratified = ms.gabor_setup.stratified_count > 0;
  d.albedo = ms.albedo ? &ms.albedo : nullptr;
  d.gabor_tile = ms.gabor_tile.get();
  d.gabor_tile_linear = ms.bake_plan.linear;
  d.intensity_lut = ms.intensity_lut ? &ms.intensity_lut : nullptr;
  d.gabor_filter = ms.material->gabor.filter == GaborParams::Filter::kAnalytic;
  // Only a material drawn in its final form switches: one with an unfinished tile (the window
  // bakes in slices) keeps the per-pixel sum filtered until the tile is there.
  d.gabor_filter_skipped = filter_negligible && (ms.gabor_tile || !ms.bake_plan.ok);
  return d;
}

}  // namespace ps
