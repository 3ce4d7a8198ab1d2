#include <nlohmann/json.hpp>

#include "render/renderer.h"

namespace ps {

namespace {
nlohmann::json vec(const glm::dvec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }
nlohmann::json ms_or_null(double ms) { return ms < 0.0 ? nlohmann::json(nullptr) : nlohmann::json(ms); }

// Pass name -> ms, plus "frame", the passes' sum in their order (with `frame_if_empty` false,
// only when there is a pass).
nlohmann::json timings(const std::vector<std::pair<std::string, double>>& passes, bool frame_if_empty) {
  nlohmann::json t = nlohmann::json::object();
  double total = 0.0;
  for (const auto& [name, ms] : passes) {
    t[name] = ms;
    total += ms;
  }
  if (frame_if_empty || !passes.empty()) t["frame"] = total;
  return t;
}

// The bake against the first frame (ms from the start of renderer creation): a window draws
// its first frame before the tiles are ready, a headless render after (docs/architecture.md).
void add_bake(const FrameStats& s, nlohmann::json& j) {
  j["gabor_bake_ms"] = s.bake_ms;
  j["gabor_bake_progress"] = s.bake_progress;
  j["gabor_tiles_ready_ms"] = ms_or_null(s.tiles_ready_ms);
  j["first_frame_ms"] = ms_or_null(s.first_frame_ms);
  j["frames_before_tiles"] = s.frames_before_tiles;
}
}  // namespace

std::string stats_json(const FrameStats& s, const std::string& backend, const std::string& egl_device,
                       const std::string& gl_renderer, int frames) {
  nlohmann::json j;
  j["backend"] = backend;
  j["egl_device"] = egl_device;
  j["gl_renderer"] = gl_renderer;
  j["frames"] = frames;
  j["reference_normal"] = vec(s.reference_normal);
  j["displacement"] = vec(s.displacement);
  j["max_penetration"] = s.max_penetration_mm;
  j["probe_position"] = vec(s.probe_position);
  j["speed_gain"] = s.speed_gain;
  j["shadow_pixels"] = s.shadow_pixels;
  j["penetrating_pixels"] = s.penetrating_pixels;
  j["drawn_pixels"] = s.drawn_pixels;  // the surface pass's; fewer on an incremental frame
  j["incremental"] = s.incremental;
  j["timings_ms"] = timings(s.timings_ms, true);
  // GPU times of the newest frame whose timer queries came back (gpu_timings_lag frames ago);
  // "frame" sums the passes, as above. {} and lag -1: none back yet.
  j["gpu_timings_ms"] = timings(s.gpu_timings_ms, false);
  j["gpu_timings_lag"] = s.gpu_timings_lag;
  j["skipped"] = s.skipped;
  add_bake(s, j);
  j["gabor_filter_skipped"] = s.gabor_filter_skipped;
  j["gabor_filter_need"] = s.gabor_filter_need;
  if (s.deformation.surfaces > 0)
    j["deformation"] = {{"surfaces", s.deformation.surfaces},
                        {"max_displacement_mm", s.deformation.max_displacement_mm},
                        {"vertices_on_probe", s.deformation.constrained},
                        {"finite", s.deformation.finite}};
  j["units"] = {{"length", "mm"}, {"speed", "mm/s"}, {"time", "ms"}};
  return j.dump(2) + "\n";
}

}  // namespace ps
