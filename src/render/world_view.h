// What the renderer draws of the haptic world over the colour image, after the pseudo-shadow
// (colour only: never the AOVs, the reductions or the displacement): the bodies as spheres of
// their radius in their material's albedo, the markers (render/world_markers.h), the probe's path
// on 4D sheets (a tube coloured by w) and the device as a faint ghost of the probe. The bodies,
// markers and hand are the view's (render/view.h); the path is drawing state, kept here between
// frames.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/result.h"
#include "passes/probe_view.h"
#include "reference/body_shadow.h"
#include "render/view.h"
#include "render/world_markers.h"
#include "scene/scene.h"

namespace ps {

// The bodies `view` draws as shadow casters (spheres of their radius), in scene order: at most
// the scene's bodies (the rest are neither drawn nor cast).
std::vector<SphereCaster> body_casters(const Scene& scene, const std::vector<glm::dvec3>& bodies_mm);

class WorldView {
 public:
  // A frame given a sheet: the probe at `probe_mm` to the path when `on_sheet` (and the path is
  // shown), coloured by `w_fraction` (its w across the surface's w range, fourd::depth_colour);
  // off every sheet (lifted) the path starts a new piece.
  void add_path_point(bool on_sheet, double w_fraction, const glm::dvec3& probe_mm);
  // Nothing to draw over `view` of `scene`.
  bool empty(const Scene& scene, const View& view) const;

  struct Frame {
    glm::dmat4 view_proj{1.0};
    const Scene* scene = nullptr;
    const View* view = nullptr;  // the bodies, markers, hand and light
    ProbeInput probe;            // as drawn this frame (after the displacement)
    glm::dvec3 probe_mm{0.0};
  };
  // Draws them over `surface`'s colour target; the passes are made on first use (their own mesh
  // caches). A pass that cannot be made draws nothing (the frame goes on without the world view).
  void run(const std::string& glsl_root, const SurfacePass& surface, const Frame& frame);

 private:
  ProbeViewPass body_view_, ghost_view_;
  bool ready_ = false;
  bool path_break_ = true;
  std::vector<WorldMarker> path_;  // the probe's path on 4D sheets: segments coloured by w
};

}  // namespace ps
