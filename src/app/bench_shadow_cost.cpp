// `pseudoshadow bench`: the pseudo-shadow's cost over plain shading of the same view.
// The default scene (the embedded scenes/default.toml) is drawn by two renderers alive at once:
// one with the probe where the scene puts it (pressed 1 mm into the plank: probe depth pass,
// pseudo-shadow, texture, reductions) and one with the probe out of reach (the plan skips all of
// that: the plain shading of the same view). Both are long-lived renderers, as in a session
// (expected_frames = 0: "auto" bakes its tile once, at creation, outside the timed frames).
// Their frames alternate in rounds so that load from other processes hits both alike; the ratio
// is of the medians of whole frames (the sum of the per-pass wall times, glFinish per pass).
// The CPU time of the whole process per frame (llvmpipe's threads included) is reported beside
// it: on a loaded machine it moves much less than wall time.
#include <time.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>

#include "app/bench_sweep.h"
#include "render/renderer.h"
#include "scene/scene_io.h"

namespace ps::bench {

namespace {

double median_of(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double process_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

// One frame of `r` with its probe put back where `s` has it (undoes the last frame's push-out);
// adds each pass's time to `passes`, the frame's total to `frames` and its CPU time to `cpu`.
Status timed_frame(Renderer& r, const Scene& s, std::map<std::string, std::vector<double>>& passes,
                   std::vector<double>& frames, std::vector<double>& cpu) {
  r.set_probe_state(s.probe.position, s.probe.velocity);
  const double cpu0 = process_cpu_ms();
  if (Status st = r.render_frame(); !st) return st;
  cpu.push_back(process_cpu_ms() - cpu0);
  double total = 0.0;
  for (const auto& [name, ms] : r.stats().timings_ms) {
    passes[name].push_back(ms);
    total += ms;
  }
  frames.push_back(total);
  return ok_status();
}

}  // namespace

Result<ShadowCost> run_shadow_cost(const BenchOptions& o, int size) {
  auto parsed = parse_scene(default_scene_text(), "<embedded default>", default_scene_base_dir());
  if (!parsed) return parsed.error();
  Scene shadow = parsed.value();
  shadow.render.width = shadow.render.height = size;
  Scene plain = shadow;
  plain.probe.position = {0.0, 0.0, 1e6};  // far beyond every influence distance; same camera
  auto made = Renderer::create(shadow, {});
  if (!made) return made.error();
  RendererOptions share;
  share.reuse_tiles_from = made.value().get();  // the same baked tile, not baked twice
  auto made_plain = Renderer::create(plain, share);
  if (!made_plain) return made_plain.error();
  Renderer& rs = *made.value();
  Renderer& rp = *made_plain.value();

  std::map<std::string, std::vector<double>> shadow_passes, plain_passes, warm;
  std::vector<double> shadow_frames, plain_frames, shadow_cpu, plain_cpu, unused, unused_cpu;
  for (int i = 0; i < std::max(o.warm_frames, 2); ++i) {  // shader JIT, caches
    if (Status st = timed_frame(rs, shadow, warm, unused, unused_cpu); !st) return st.error();
    if (Status st = timed_frame(rp, plain, warm, unused, unused_cpu); !st) return st.error();
  }
  // Two frames of ~10 ms that differ by a few ms: pooled over alternated rounds, as the
  // untextured ratio is (a shared 2-core machine moves single frames by 10-30 %).
  const int rounds = std::max(o.rounds, 7), per_round = std::max(o.timed_frames, 8);
  for (int round = 0; round < rounds; ++round)
    for (int k = 0; k < 2 * per_round; ++k) {
      const bool s = (k % 2 == 0) == (round % 2 == 0);  // alternate, and which goes first
      Status st = s ? timed_frame(rs, shadow, shadow_passes, shadow_frames, shadow_cpu)
                    : timed_frame(rp, plain, plain_passes, plain_frames, plain_cpu);
      if (!st) return st.error();
    }
  ShadowCost c;
  c.size = size;
  c.shadow_frame_ms = median_of(shadow_frames);
  c.plain_frame_ms = median_of(plain_frames);
  c.ratio = c.shadow_frame_ms / c.plain_frame_ms;
  c.cpu_ratio = median_of(shadow_cpu) / median_of(plain_cpu);
  for (const char* pass : {"probe_depth", "surface", "reductions"})
    c.shadow_pass_ms.emplace_back(pass, median_of(shadow_passes[pass]));
  c.plain_surface_ms = median_of(plain_passes["surface"]);
  c.shadow_pixels = rs.stats().shadow_pixels;
  return c;
}

Result<DistanceCost> run_distance_cost(const BenchOptions& o, const std::string& scene_path, int size) {
  auto parsed = load_scene(scene_path, {"render.size=[" + std::to_string(size) + "," + std::to_string(size) + "]"});
  if (!parsed) return parsed.error();
  Scene plane = parsed.value();
  Scene normal = plane;
  plane.render.shadow_distance = ShadowDistance::kReferencePlane;
  normal.render.shadow_distance = ShadowDistance::kSurfaceNormal;
  auto made_plane = Renderer::create(plane, {});
  if (!made_plane) return made_plane.error();
  RendererOptions share;
  share.reuse_tiles_from = made_plane.value().get();
  auto made_normal = Renderer::create(normal, share);
  if (!made_normal) return made_normal.error();
  std::map<std::string, std::vector<double>> plane_passes, normal_passes, warm;
  std::vector<double> plane_frames, normal_frames, cpu, unused;
  for (int i = 0; i < std::max(o.warm_frames, 2); ++i) {
    if (Status st = timed_frame(*made_plane.value(), plane, warm, unused, cpu); !st) return st.error();
    if (Status st = timed_frame(*made_normal.value(), normal, warm, unused, cpu); !st) return st.error();
  }
  const int rounds = std::max(o.rounds, 5), per_round = std::max(o.timed_frames, 4);
  for (int round = 0; round < rounds; ++round)
    for (int k = 0; k < 2 * per_round; ++k) {
      const bool first = (k % 2 == 0) == (round % 2 == 0);
      Status st = first ? timed_frame(*made_plane.value(), plane, plane_passes, plane_frames, cpu)
                        : timed_frame(*made_normal.value(), normal, normal_passes, normal_frames, cpu);
      if (!st) return st.error();
    }
  DistanceCost c;
  c.scene = std::filesystem::path(scene_path).stem().string();
  c.size = size;
  c.plane_frame_ms = median_of(plane_frames);
  c.normal_frame_ms = median_of(normal_frames);
  c.ratio = c.normal_frame_ms / c.plane_frame_ms;
  c.plane_surface_ms = median_of(plane_passes["surface"]);
  c.normal_surface_ms = median_of(normal_passes["surface"]);
  c.surface_ratio = c.normal_surface_ms / c.plane_surface_ms;
  return c;
}

Result<LutCost> run_lut_cost(const BenchOptions& o, const std::string& table, int size) {
  const std::string size_set = "render.size=[" + std::to_string(size) + "," + std::to_string(size) + "]";
  auto formula = parse_scene(default_scene_text(), "<embedded default>", default_scene_base_dir(), {size_set});
  if (!formula) return formula.error();
  auto lut = parse_scene(default_scene_text(), "<embedded default>", default_scene_base_dir(),
                         {size_set, "materials.wood.intensity_lut=\"" + table + "\""});
  if (!lut) return lut.error();
  auto made_formula = Renderer::create(formula.value(), {});
  if (!made_formula) return made_formula.error();
  RendererOptions share;
  share.reuse_tiles_from = made_formula.value().get();
  auto made_lut = Renderer::create(lut.value(), share);
  if (!made_lut) return made_lut.error();
  std::map<std::string, std::vector<double>> formula_passes, lut_passes, warm;
  std::vector<double> formula_frames, lut_frames, cpu, unused;
  for (int i = 0; i < std::max(o.warm_frames, 2); ++i) {
    if (Status st = timed_frame(*made_formula.value(), formula.value(), warm, unused, cpu); !st) return st.error();
    if (Status st = timed_frame(*made_lut.value(), lut.value(), warm, unused, cpu); !st) return st.error();
  }
  const int rounds = std::max(o.rounds, 7), per_round = std::max(o.timed_frames, 8);
  for (int round = 0; round < rounds; ++round)
    for (int k = 0; k < 2 * per_round; ++k) {
      const bool first = (k % 2 == 0) == (round % 2 == 0);
      Status st = first ? timed_frame(*made_formula.value(), formula.value(), formula_passes, formula_frames, cpu)
                        : timed_frame(*made_lut.value(), lut.value(), lut_passes, lut_frames, cpu);
      if (!st) return st.error();
    }
  LutCost c;
  c.size = size;
  c.formula_frame_ms = median_of(formula_frames);
  c.lut_frame_ms = median_of(lut_frames);
  c.ratio = c.lut_frame_ms / c.formula_frame_ms;
  c.formula_surface_ms = median_of(formula_passes["surface"]);
  c.lut_surface_ms = median_of(lut_passes["surface"]);
  c.surface_ratio = c.lut_surface_ms / c.formula_surface_ms;
  return c;
}

}  // namespace ps::bench
