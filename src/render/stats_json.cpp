#include <nlohmann/json.hpp>

#include "render/renderer.h"

namespace ps {

namespace {
nlohmann::json vec(const glm::dvec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }
nlohmann::json ms_or_null(double ms) { return ms < 0.0 ? nlohmann::json(nullptr) : nlohmann::json(ms); }
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
  nlohmann::json t = nlohmann::json::object();
  double total = 0.0;
  for (const auto& [name, ms] : s.timings_ms) {
    t[name] = ms;
    total += ms;
  }
  t["frame"] = total;
  j["timings_ms"] = t;
  // GPU times of the newest frame whose timer queries came back (gpu_timings_lag frames ago);
  // "frame" sums the passes, as above. {} and lag -1: none back yet.
  nlohmann::json g = nlohmann::json::object();
  double gpu_total = 0.0;
  for (const auto& [name, ms] : s.gpu_timings_ms) {
    g[name] = ms;
    gpu_total += ms;
  }
  if (!s.gpu_timings_ms.empty()) g["frame"] = gpu_total;
  j["gpu_timings_ms"] = g;
  j["gpu_timings_lag"] = s.gpu_timings_lag;
  j["skipped"] = s.skipped;
  // The bake against the first frame (ms from the start of renderer creation): a window draws
  // its first frame before the tiles are ready, a headless render after (docs/architecture.md).
  j["gabor_bake_ms"] = s.bake_ms;
  j["gabor_bake_progress"] = s.bake_progress;
  j["gabor_tiles_ready_ms"] = ms_or_null(s.tiles_ready_ms);
  j["first_frame_ms"] = ms_or_null(s.first_frame_ms);
  j["frames_before_tiles"] = s.frames_before_tiles;
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
