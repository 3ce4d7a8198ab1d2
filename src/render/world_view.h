// What the renderer draws of the haptic world over the colour image, after the pseudo-shadow
// (colour only: never the AOVs, the reductions or the displacement): the bodies as spheres of
// their radius in their material's albedo, the markers (render/world_markers.h), the probe's path
// on 4D sheets (a tube coloured by w) and the device as a faint ghost of the probe. Holds what the
// frame inputs gave of them (FrameInput::bodies_mm, markers, device_mm, sheet) between frames.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/result.h"
#include "passes/probe_view.h"
#include "reference/body_shadow.h"
#include "render/world_markers.h"
#include "scene/scene.h"

namespace ps {

class WorldView {
 public:
  // At most `scene_bodies` positions are kept: the rest are neither drawn nor cast.
  void set_bodies(const std::vector<glm::dvec3>& positions, std::size_t scene_bodies);
  void set_markers(std::vector<WorldMarker> markers) { markers_ = std::move(markers); }
  void set_device(const glm::dvec3& device_mm) { device_mm_ = device_mm; }
  void set_show_device(bool show) { show_device_ = show; }
  bool show_device() const { return show_device_; }
  void set_show_path(bool show) { show_path_ = show; }
  // A frame given a sheet: the probe at `probe_mm` to the path when shown and `on_sheet`, coloured
  // by `w_fraction` (its w across the surface's w range, fourd::depth_colour); off every sheet
  // (lifted) the path starts a new piece.
  void add_path_point(bool on_sheet, double w_fraction, const glm::dvec3& probe_mm);

  // The bodies drawn this frame as shadow casters (spheres of their radius), in scene order.
  std::vector<SphereCaster> body_casters(const Scene& scene) const;
  bool empty() const { return body_mm_.empty() && markers_.empty() && !show_device_ && path_.empty(); }

  struct Frame {
    glm::dmat4 view_proj{1.0};
    const Light* light = nullptr;
    const Scene* scene = nullptr;
    ProbeInput probe;            // as drawn this frame (after the displacement)
    glm::dvec3 probe_mm{0.0};
  };
  // Draws them over `surface`'s colour target; the passes are made on first use (their own mesh
  // caches). A pass that cannot be made draws nothing (the frame goes on without the world view).
  void run(const std::string& glsl_root, const SurfacePass& surface, const Frame& frame);

 private:
  ProbeViewPass body_view_, ghost_view_;
  bool ready_ = false;
  std::vector<glm::dvec3> body_mm_;  // at most Scene::bodies.size()
  std::vector<WorldMarker> markers_;
  glm::dvec3 device_mm_{0.0};
  bool show_device_ = false;
  bool show_path_ = false;
  bool path_break_ = true;
  std::vector<WorldMarker> path_;  // the probe's path on 4D sheets: segments coloured by w
};

}  // namespace ps
