// The parts of a frame's surface draws (Renderer::surface_draws): the values every surface of the
// frame shares, and the fields of a draw its material decides.
#pragma once

#include "passes/surface.h"
#include "render/material_gpu.h"
#include "render/plan.h"
#include "reference/probe_geometry.h"
#include "scene/scene.h"

namespace ps {

struct RendererOptions;

// What every surface of the frame shares: the camera, the reference plane, the depth window, the
// light and the probe's height range (and its capsule, for the closed-form distance).
SurfaceFrame surface_frame(const RenderSettings& rs, const Camera& camera, const Light& light, const PlaneFrame& frame,
                           const FramePlan& plan, const BoundingSphere& probe, const Probe& p,
                           const RendererOptions& options);

// A draw with the fields material `ms` decides: its variant's Gabor inputs (stratified, tile,
// filter) and its textures. `filter_negligible`: the last frame measured the filter's need as
// negligible (RendererOptions::filter_lod).
SurfaceDraw material_draw(const MaterialGpu& ms, bool filter_negligible);

}  // namespace ps
