#include "app/bench/bench_sweep.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "prepare/prepare.h"
#include "reference/gabor.h"
#include "render/renderer.h"

namespace ps::bench {

namespace {

constexpr double kViewMm = 60.0;          // ortho view height at 512^2
constexpr double kProbeRadiusMm = 25.0;
constexpr double kPenetrationMm = 0.5;
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

double median(std::vector<double> v) {
  if (v.empty()) return kNan;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// World (x, y) of pixel (px, py), row 0 = top, for bench_scene's camera.
glm::dvec2 pixel_world(const Scene& s, int px, int py) {
  const double h = s.camera.ortho_height_mm, w = h * s.render.width / s.render.height;
  return {(px + 0.5) / s.render.width * w - 0.5 * w, 0.5 * h - (py + 0.5) / s.render.height * h};
}

// CPU Gabor reference of the scene's material per pixel, in that material's sigmas.
std::vector<double> texture_reference(const Scene& s) {
  const GaborParams& g = s.materials[0].gabor;
  const GaborSetup setup = make_gabor_setup(g);
  std::vector<double> ref(static_cast<size_t>(s.render.width) * s.render.height);
  for (int y = 0; y < s.render.height; ++y)
    for (int x = 0; x < s.render.width; ++x) {
      const glm::dvec2 w = pixel_world(s, x, y);
      ref[static_cast<size_t>(y) * s.render.width + x] =
          gabor_noise(g, setup, s.render.seed, w.x, w.y) / setup.sigma_unit;
    }
  return ref;
}

struct TextureRefs {
  const std::vector<double>* target = nullptr;  // baseline material at this image size
  bool ideal = false;                           // also compare with untruncated kernels
};

// RMS texture errors over the footprint pixels listed in `pix` (x, y).
// `plan`: the tile the renderer drew with (ok == false: the per-pixel sum).
void texture_errors(const Scene& s, const Image& tex, const std::vector<glm::ivec2>& pix,
                    const GaborBakePlan& plan, const TextureRefs& refs, Measurement& m) {
  const GaborParams& g = s.materials[0].gabor;
  const GaborSetup setup = make_gabor_setup(g);
  double own = 0.0, ideal = 0.0, target = 0.0;
  for (const glm::ivec2& p : pix) {
    const glm::dvec2 w = pixel_world(s, p.x, p.y);
    const double t = tex.at(p.x, p.y, 0);
    // Each strategy against its own CPU twin (baked: the same Hermite lookup in double).
    const double own_ref = plan.ok ? gabor_noise_baked(g, setup, plan, s.render.seed, w.x, w.y)
                                   : gabor_noise(g, setup, s.render.seed, w.x, w.y);
    const double e = t - own_ref / setup.sigma_unit;
    own += e * e;
    if (refs.ideal) {
      const double ei = t - gabor_noise_untruncated(g, setup, s.render.seed, w.x, w.y) / setup.sigma_unit;
      ideal += ei * ei;
    }
    if (refs.target) {
      const double et = t - (*refs.target)[static_cast<size_t>(p.y) * s.render.width + p.x];
      target += et * et;
    }
  }
  const double n = pix.empty() ? kNan : static_cast<double>(pix.size());
  m.texture_rms_sigma = std::sqrt(own / n);
  m.texture_vs_ideal = refs.ideal ? std::sqrt(ideal / n) : kNan;
  m.texture_vs_target = refs.target ? std::sqrt(target / n) : kNan;
}

// Errors of one rendered frame against the analytic scene and the texture references.
void frame_errors(const Scene& s, const Renderer& r, const TextureRefs& refs, Measurement& m) {
  const Image tex = r.read_aov("texture").value(), dist = r.read_aov("distance").value();
  const Image inten = r.read_aov("intensity").value();
  const glm::dvec3 c = s.probe.position;
  const double rad = s.probe.radius_mm, onset = s.materials[0].onset_distance_mm;
  std::vector<glm::ivec2> pix;
  m.distance_max_mm = 0.0;
  for (int y = 0; y < s.render.height; ++y)
    for (int x = 0; x < s.render.width; ++x) {
      if (!(inten.at(x, y, 0) > 0.0f)) continue;
      const double d = dist.at(x, y, 0);
      const glm::dvec2 w = pixel_world(s, x, y);
      const double rho2 = (w.x - c.x) * (w.x - c.x) + (w.y - c.y) * (w.y - c.y);
      // Inside 0.9 r: the silhouette's infinite slope would make any texel look wrong.
      if (rho2 < 0.81 * rad * rad && !std::isnan(d))  // NaN: no probe above the pixel
        m.distance_max_mm = std::max(m.distance_max_mm, std::abs(d - (c.z - std::sqrt(rad * rad - rho2))));
      if (d < onset) pix.emplace_back(x, y);
    }
  m.footprint_pixels = static_cast<int>(pix.size());
  texture_errors(s, tex, pix, r.gabor_bake_plan(0), refs, m);
  const double pen = s.probe.radius_mm - s.probe.position.z;  // plane z = 0
  m.displacement_rel = pen > 0.0 ? std::abs(r.stats().displacement.z - pen) / pen : kNan;
  const double cz = std::clamp(r.stats().reference_normal.z, -1.0, 1.0);
  m.normal_deg = std::acos(cz) * 180.0 / 3.141592653589793;
}

Result<Measurement> measure_with(const Scene& s, const BenchOptions& o, const TextureRefs& refs,
                                 bool errors = true) {
  auto rr = open_renderer(s, {});
  if (!rr) return rr.error();
  Renderer& r = *rr.value();
  Measurement m;
  std::vector<double>& frame = m.frame_samples;
  std::vector<double>& surface = m.surface_samples;
  std::vector<double> gpu;
  for (int i = 0; i < o.warm_frames + o.timed_frames; ++i) {
    // The probe put back where the scene has it (undoes the last frame's push).
    if (auto st = r.render(probe_frame_input(s.probe.position, s.probe.velocity)); !st) return st.error();
    if (i == 0 && errors) frame_errors(s, r, refs, m);
    if (i < o.warm_frames) continue;
    double total = 0.0, surf = 0.0;
    for (const auto& [name, ms] : r.stats().timings_ms) {
      total += ms;
      if (name == "surface") surf = ms;
    }
    frame.push_back(total);
    surface.push_back(surf);
    if (r.stats().gpu_timings_ms.empty()) continue;
    double gpu_total = 0.0;
    for (const auto& [name, ms] : r.stats().gpu_timings_ms) gpu_total += ms;
    gpu.push_back(gpu_total);
  }
  m.frame_ms = median(frame);
  m.surface_ms = median(surface);
  if (!gpu.empty()) m.gpu_frame_ms = median(gpu);
  return m;
}

}  // namespace

Scene bench_scene(int size) {
  Scene s;
  s.path = "<bench>";
  s.camera.projection = Projection::kOrthographic;
  s.camera.position = {0.0, 0.0, 100.0};
  s.camera.up = {0.0, 1.0, 0.0};
  s.camera.ortho_height_mm = kViewMm;
  s.render.width = s.render.height = size;
  Material m;
  m.name = "bench";
  m.gabor.lambda_min_mm = 0.8;
  m.gabor.lambda_max_mm = 2.0;
  m.gabor.theta_max_rad = 1.0;
  m.onset_distance_mm = 100.0;  // the whole footprint is textured: the Gabor cost is visible
  // The strategies' errors are against the point-sampled CPU twins; what filtering costs and
  // buys is `bench --texture-filter` (bench_texture_filter.h).
  m.gabor.filter = GaborParams::Filter::kNone;
  // The sweep's base is the naive sum (the thesis's method, the baseline every strategy is
  // judged against, and what the impulse and truncation knobs change); the scene default
  // "auto" is its own row of the gabor_strategy group.
  m.gabor.strategy = GaborParams::Strategy::kNaive;
  s.materials.push_back(m);
  Surface p;
  p.material = "bench";
  p.size_mm = {400.0, 400.0};
  p.resolution = 4;
  s.surfaces.push_back(p);
  s.probe.radius_mm = kProbeRadiusMm;
  s.probe.position = {0.0, 0.0, kProbeRadiusMm - kPenetrationMm};
  return s;
}

Result<Measurement> measure(const Scene& scene, const BenchOptions& o) {
  return measure_with(scene, o, TextureRefs{});
}

namespace {

struct Knob {
  std::string group, value, metric;
  std::function<void(Scene&)> edit;
};

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof(b), "%g", v);
  return b;
}

// Every knob, in the table's row order: one list, read top to bottom, so kept whole (48 lines).
std::vector<Knob> knobs() {
  std::vector<Knob> k;
  for (int s : {128, 256, 512, 1024})  // surface + reduction targets (image) resolution
    k.push_back({"reduction_base", num(s), "displacement_rel", [s](Scene& sc) {
                   sc.render.width = sc.render.height = s;
                   sc.render.displacement = DisplacementMethod::kExactMax;
                 }});
  for (int s : {64, 128, 256, 512, 1024})
    k.push_back({"depth_map", num(s), "distance_max_mm", [s](Scene& sc) { sc.render.depth_map_size = s; }});
  for (double n : {2.0, 5.0, 10.0, 25.0, 50.0})
    k.push_back({"gabor_n", num(n), "texture_vs_target", [n](Scene& sc) {
                   sc.materials[0].gabor.n_min = sc.materials[0].gabor.n_max = n;
                 }});
  for (double t : {0.3, 0.2, 0.1, 0.05, 0.01})
    k.push_back({"gabor_truncation", num(t), "texture_vs_ideal",
                 [t](Scene& sc) { sc.materials[0].gabor.truncation = t; }});
  // Strategies are judged against the naive texture (the default): RMS <= 1 % of sigma and
  // >= 10x faster would be needed to replace it.
  k.push_back({"gabor_strategy", "naive", "texture_vs_target", [](Scene&) {}});
  for (int c : {1, 2, 4, 8})
    k.push_back({"gabor_strategy", "stratified_" + num(c), "texture_vs_target", [c](Scene& sc) {
                   sc.materials[0].gabor.strategy = GaborParams::Strategy::kStratified;
                   sc.materials[0].gabor.stratified_impulses = c;
                 }});
  // "none": the same frame without any Gabor evaluation (error = the whole texture, 1 sigma);
  // subtracting its time gives the Gabor evaluation's own cost.
  k.push_back({"gabor_strategy", "none", "texture_vs_target", [](Scene& sc) { sc.materials[0].textured = false; }});
  k.push_back({"gabor_strategy", "auto", "texture_vs_target",
               [](Scene& sc) { sc.materials[0].gabor.strategy = GaborParams::Strategy::kAuto; }});
  for (int spl : {8, 16, 32})  // tile samples per lambda_min; the bake itself is not timed
    k.push_back({"gabor_strategy", "baked_" + num(spl), "texture_vs_target", [spl](Scene& sc) {
                   sc.materials[0].gabor.strategy = GaborParams::Strategy::kBaked;
                   sc.materials[0].gabor.bake_samples_per_lambda = spl;
                 }});
  for (int spl : {16, 24, 32})  // bilinear lookup of a values-only tile
    k.push_back({"gabor_strategy", "baked_linear_" + num(spl), "texture_vs_target", [spl](Scene& sc) {
                   sc.materials[0].gabor.strategy = GaborParams::Strategy::kBakedLinear;
                   sc.materials[0].gabor.bake_samples_per_lambda = spl;
                 }});
  for (double c : {5.0, 10.0, 20.0, 40.0})
    k.push_back({"displacement", "weighted_c" + num(c), "displacement_rel", [c](Scene& sc) {
                   sc.render.displacement = DisplacementMethod::kWeightedAverage;
                   sc.render.weight_exponent = c;
                 }});
  k.push_back({"displacement", "exact_max", "displacement_rel",
               [](Scene& sc) { sc.render.displacement = DisplacementMethod::kExactMax; }});
  return k;
}

double metric_value(const std::string& metric, const Measurement& m) {
  if (metric == "displacement_rel") return m.displacement_rel;
  if (metric == "distance_max_mm") return m.distance_max_mm;
  if (metric == "texture_vs_ideal") return m.texture_vs_ideal;
  if (metric == "texture_vs_target") return m.texture_vs_target;
  return m.texture_rms_sigma;
}

void mark_pareto(std::vector<BenchRow>& rows) {
  for (BenchRow& a : rows) {
    a.pareto = std::isfinite(a.error);
    for (const BenchRow& b : rows) {
      if (&a == &b || b.group != a.group || !std::isfinite(b.error)) continue;
      const bool no_worse = b.m.frame_ms <= a.m.frame_ms && b.error <= a.error;
      const bool better = b.m.frame_ms < a.m.frame_ms || b.error < a.error;
      if (no_worse && better) a.pareto = false;
    }
  }
}

}  // namespace

namespace {

// Adds another round's timings to `into` and re-takes the medians.
void pool(Measurement& into, const Measurement& more) {
  into.frame_samples.insert(into.frame_samples.end(), more.frame_samples.begin(), more.frame_samples.end());
  into.surface_samples.insert(into.surface_samples.end(), more.surface_samples.begin(), more.surface_samples.end());
  into.frame_ms = median(into.frame_samples);
  into.surface_ms = median(into.surface_samples);
}

}  // namespace

Result<std::vector<BenchRow>> run_sweep(const BenchOptions& o) {
  const Scene base = bench_scene(o.size);
  if (o.progress) o.progress("CPU reference texture " + num(o.size) + "^2 ...");
  const std::vector<double> ref = texture_reference(base);
  std::vector<BenchRow> rows;
  const std::vector<Knob> ks = knobs();
  for (int round = 0; round < std::max(1, o.rounds); ++round)
    for (size_t i = 0; i < ks.size(); ++i) {
      Scene s = base;
      ks[i].edit(s);
      const bool same_size = s.render.width == base.render.width;
      // Errors are deterministic: computed in the first round only.
      const TextureRefs refs{same_size ? &ref : nullptr,
                             ks[i].metric == "texture_vs_ideal" || ks[i].group == "gabor_strategy"};
      auto m = measure_with(s, o, round == 0 ? refs : TextureRefs{}, round == 0);
      if (!m) return m.error();
      if (round == 0)
        rows.push_back({ks[i].group, ks[i].value, ks[i].metric, m.value(), metric_value(ks[i].metric, m.value()), false});
      else
        pool(rows[i].m, m.value());
      if (o.progress)
        o.progress("round " + num(round + 1.0) + "/" + num(double(o.rounds)) + " [" + num(i + 1.0) + "/" +
                   num(double(ks.size())) + "] " + rows[i].group + "=" + rows[i].value + ": " +
                   num(rows[i].m.frame_ms) + " ms, " + rows[i].metric + " " + num(rows[i].error));
    }
  mark_pareto(rows);
  return rows;
}

namespace {

// Least-squares slope of y over x.
double slope(const std::vector<double>& x, const std::vector<double>& y) {
  double mx = 0, my = 0, sxy = 0, sxx = 0;
  for (size_t i = 0; i < x.size(); ++i) mx += x[i] / x.size(), my += y[i] / y.size();
  for (size_t i = 0; i < x.size(); ++i) sxy += (x[i] - mx) * (y[i] - my), sxx += (x[i] - mx) * (x[i] - mx);
  return sxx > 0 ? sxy / sxx : kNan;
}

}  // namespace

namespace {

// Probe beyond influence: the whole frame over the plain shading pass it contains.
Result<double> beyond_influence_ratio(const BenchOptions& o) {
  Scene far = bench_scene(o.size);
  far.probe.position = {0.0, 0.0, 1e6};
  auto m = measure(far, o);
  if (!m) return m.error();
  return m->frame_ms / m->surface_ms;
}

// PS_TEXTURED=0 versus the textured variant with no fragment inside the onset distance.
Result<double> untextured_ratio(const BenchOptions& options) {
  // Two ~8 ms frames that differ by a few percent at most: with the sweep's 3 x 3 frames the
  // ratio scattered from 0.87 to 1.25 between runs on a shared machine, so this one pools
  // 7 alternated rounds of 12 frames each.
  BenchOptions o = options;
  o.timed_frames = std::max(o.timed_frames, 12);
  o.rounds = std::max(o.rounds, 7);
  Scene untex = bench_scene(o.size), idle = bench_scene(o.size);
  untex.probe.position.z = idle.probe.position.z = kProbeRadiusMm + 1.0;  // no contact: d > 0
  untex.materials[0].textured = false;
  idle.materials[0].onset_distance_mm = 0.0;
  Measurement pu, pi;  // alternated so both see the same machine load
  for (int round = 0; round < std::max(1, o.rounds); ++round) {
    auto mu = measure(untex, o);
    if (!mu) return mu.error();
    auto mi = measure(idle, o);
    if (!mi) return mi.error();
    pool(pu, mu.value());
    pool(pi, mi.value());
  }
  return pu.frame_ms / pi.frame_ms;
}

// Surface-pass slopes: vs textured footprint pixels (radius sweep) and vs screen pixels at a
// fixed footprint (same mm per pixel at every size).
Status slopes(const BenchOptions& o, SkipRatios& out) {
  std::vector<double> fx, fy, sx, sy;
  for (double r : {5.0, 10.0, 15.0, 20.0, 25.0}) {
    Scene s = bench_scene(o.size);
    s.probe.radius_mm = r;
    s.probe.position.z = r - kPenetrationMm;
    auto m = measure(s, o);
    if (!m) return m.error();
    fx.push_back(m->footprint_pixels / 1000.0);
    fy.push_back(m->surface_ms);
  }
  for (int size : {256, 512, 1024}) {
    Scene s = bench_scene(size);
    s.camera.ortho_height_mm = kViewMm * size / o.size;
    s.probe.radius_mm = 10.0;
    s.probe.position.z = 10.0 - kPenetrationMm;
    auto m = measure(s, o);
    if (!m) return m.error();
    sx.push_back(double(size) * size / 1000.0);
    sy.push_back(m->surface_ms);
  }
  out.ms_per_kpx_footprint = slope(fx, fy);
  out.ms_per_kpx_screen = slope(sx, sy);
  return ok_status();
}

}  // namespace

Result<SkipRatios> run_skip_ratios(const BenchOptions& o) {
  SkipRatios out;
  auto b = beyond_influence_ratio(o);
  if (!b) return b.error();
  out.beyond_influence = b.value();
  auto u = untextured_ratio(o);
  if (!u) return u.error();
  out.untextured = u.value();
  if (Status st = slopes(o, out); !st) return st.error();
  for (int size : {512, 1024}) {
    auto c = run_shadow_cost(o, size);
    if (!c) return c.error();
    out.shadow_cost.push_back(c.value());
  }
  return out;
}

}  // namespace ps::bench
