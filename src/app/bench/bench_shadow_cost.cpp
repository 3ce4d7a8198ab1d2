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
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>

#include "app/bench/bench_sweep.h"
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
                   std::vector<double>& frames, std::vector<double>& cpu, std::vector<double>* gpu = nullptr) {
  const FrameInput at_scene_probe = probe_frame_input(s.probe.position, s.probe.velocity);
  const double cpu0 = process_cpu_ms();
  if (auto st = r.render(at_scene_probe); !st) return st.error();
  cpu.push_back(process_cpu_ms() - cpu0);
  double total = 0.0;
  for (const auto& [name, ms] : r.stats().timings_ms) {
    passes[name].push_back(ms);
    total += ms;
  }
  frames.push_back(total);
  if (gpu != nullptr && !r.stats().gpu_timings_ms.empty()) {
    double gpu_total = 0.0;
    for (const auto& [name, ms] : r.stats().gpu_timings_ms) gpu_total += ms;
    gpu->push_back(gpu_total);
  }
  return ok_status();
}

// One renderer in a timed comparison: its scene, and what its frames measured.
struct Contender {
  Renderer* renderer = nullptr;
  const Scene* scene = nullptr;
  std::map<std::string, std::vector<double>> passes;
  std::vector<double> frames, cpu, gpu;  // gpu: GL timer queries' frame, where they came back
};

// Warm-up frames for every contender, then `rounds` rounds of per_round frames each, the
// contenders taking turns and each round starting with the next one, so that load from other
// processes hits all of them alike.
Status alternate(const BenchOptions& o, std::vector<Contender>& cs, int rounds, int per_round) {
  std::map<std::string, std::vector<double>> warm;
  std::vector<double> unused, unused_cpu;
  for (int i = 0; i < std::max(o.warm_frames, 2); ++i)  // shader JIT, caches
    for (Contender& c : cs)
      if (Status st = timed_frame(*c.renderer, *c.scene, warm, unused, unused_cpu); !st) return st;
  const int n = static_cast<int>(cs.size());
  for (int round = 0; round < rounds; ++round)
    for (int k = 0; k < n * per_round; ++k) {
      Contender& c = cs[static_cast<size_t>((k + round) % n)];
      if (Status st = timed_frame(*c.renderer, *c.scene, c.passes, c.frames, c.cpu, &c.gpu); !st) return st;
    }
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

  // Two frames of ~10 ms that differ by a few ms: pooled over alternated rounds, as the
  // untextured ratio is (a shared 2-core machine moves single frames by 10-30 %).
  std::vector<Contender> cs(2);
  cs[0].renderer = &rs, cs[0].scene = &shadow;
  cs[1].renderer = &rp, cs[1].scene = &plain;
  if (Status st = alternate(o, cs, std::max(o.rounds, 7), std::max(o.timed_frames, 8)); !st) return st.error();
  ShadowCost c;
  c.size = size;
  c.shadow_frame_ms = median_of(cs[0].frames);
  c.plain_frame_ms = median_of(cs[1].frames);
  c.ratio = c.shadow_frame_ms / c.plain_frame_ms;
  c.cpu_ratio = median_of(cs[0].cpu) / median_of(cs[1].cpu);
  for (const char* pass : {"probe_depth", "surface", "reductions"})
    c.shadow_pass_ms.emplace_back(pass, median_of(cs[0].passes[pass]));
  c.plain_surface_ms = median_of(cs[1].passes["surface"]);
  c.shadow_pixels = rs.stats().shadow_pixels;
  if (!cs[0].gpu.empty() && !cs[1].gpu.empty()) {
    c.gpu_shadow_frame_ms = median_of(cs[0].gpu);
    c.gpu_plain_frame_ms = median_of(cs[1].gpu);
  }
  return c;
}

namespace {

// The largest and the mean |a - b| of the distance AOVs where both have a probe above the pixel
// (NaN: none), and how many such pixels there are.
struct AovDifference {
  double max = 0.0, mean = 0.0;
  long pixels = 0;
};
Result<AovDifference> distance_difference(const Renderer& a, const Renderer& b) {
  auto da = a.read_aov("distance");
  if (!da) return da.error();
  auto db = b.read_aov("distance");
  if (!db) return db.error();
  AovDifference d;
  double sum = 0.0;
  for (size_t i = 0; i < da->pixels.size() && i < db->pixels.size(); ++i) {
    const float x = da->pixels[i], y = db->pixels[i];
    if (std::isnan(x) || std::isnan(y)) continue;
    d.max = std::max(d.max, std::abs(static_cast<double>(x) - y));
    sum += std::abs(static_cast<double>(x) - y);
    ++d.pixels;
  }
  d.mean = d.pixels > 0 ? sum / static_cast<double>(d.pixels) : 0.0;
  return d;
}

// The contenders' (plane, normal, marched) median frame and surface-pass times, and their ratios.
void distance_times(std::vector<Contender>& cs, DistanceCost& c) {
  c.plane_frame_ms = median_of(cs[0].frames);
  c.normal_frame_ms = median_of(cs[1].frames);
  c.marched_frame_ms = median_of(cs[2].frames);
  c.ratio = c.normal_frame_ms / c.plane_frame_ms;
  c.marched_ratio = c.marched_frame_ms / c.plane_frame_ms;
  c.plane_surface_ms = median_of(cs[0].passes["surface"]);
  c.normal_surface_ms = median_of(cs[1].passes["surface"]);
  c.surface_ratio = c.normal_surface_ms / c.plane_surface_ms;
}

// How far the plane's and the march's distances are from the normal's. The last frame of each
// drew the same probe position (timed_frame puts it back).
Status distance_offsets(const std::vector<Contender>& cs, DistanceCost& c) {
  auto plane_off = distance_difference(*cs[0].renderer, *cs[1].renderer);
  if (!plane_off) return plane_off.error();
  auto march_off = distance_difference(*cs[2].renderer, *cs[1].renderer);
  if (!march_off) return march_off.error();
  c.plane_vs_normal_max_mm = plane_off->max;
  c.plane_vs_normal_mean_mm = plane_off->mean;
  c.marched_vs_normal_max_mm = march_off->max;
  c.marched_vs_normal_mean_mm = march_off->mean;
  c.compared_pixels = march_off->pixels;
  return ok_status();
}

}  // namespace

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
  share.closed_form_normal_distance = false;  // the depth-map march (a mesh probe's way)
  auto made_marched = Renderer::create(normal, share);
  if (!made_marched) return made_marched.error();
  std::vector<Contender> cs(3);
  cs[0].renderer = made_plane.value().get(), cs[0].scene = &plane;
  cs[1].renderer = made_normal.value().get(), cs[1].scene = &normal;
  cs[2].renderer = made_marched.value().get(), cs[2].scene = &normal;
  if (Status st = alternate(o, cs, std::max(o.rounds, 5), std::max(o.timed_frames, 4)); !st) return st.error();
  DistanceCost c;
  c.scene = std::filesystem::path(scene_path).stem().string();
  c.size = size;
  distance_times(cs, c);
  if (Status st = distance_offsets(cs, c); !st) return st.error();
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
  std::vector<Contender> cs(2);
  cs[0].renderer = made_formula.value().get(), cs[0].scene = &formula.value();
  cs[1].renderer = made_lut.value().get(), cs[1].scene = &lut.value();
  if (Status st = alternate(o, cs, std::max(o.rounds, 7), std::max(o.timed_frames, 8)); !st) return st.error();
  LutCost c;
  c.size = size;
  c.formula_frame_ms = median_of(cs[0].frames);
  c.lut_frame_ms = median_of(cs[1].frames);
  c.ratio = c.lut_frame_ms / c.formula_frame_ms;
  c.formula_surface_ms = median_of(cs[0].passes["surface"]);
  c.lut_surface_ms = median_of(cs[1].passes["surface"]);
  c.surface_ratio = c.lut_surface_ms / c.formula_surface_ms;
  return c;
}

}  // namespace ps::bench
