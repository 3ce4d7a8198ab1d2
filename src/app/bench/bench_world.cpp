// `bench_world`: closest-point queries of the haptic scene (Google Benchmark). Per query p50 /
// p99 in microseconds and the local model (triangles examined per query vs overall), on
// Suzanne (the Table 5.1 monkey head, x22) and on a generated 102 400-triangle torus; the same
// queries by brute force over every triangle (why a BVH); a whole god-object move on Suzanne.
// Numbers only: nothing here passes or fails (docs/haptics.md, "Haptic geometry").
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <random>

#include <time.h>

#include "haptics/loop_stats.h"
#include "scene/mesh.h"
#include "scene/mesh_procedural.h"
#include "world/god_object.h"

namespace ps::world {
namespace {

constexpr double kProbeRadiusMm = 8.0;     // the scenes' fingertip probe
constexpr double kQueryRadiusMm = kProbeRadiusMm + 0.5 + 2.0;  // R + margin + a 2 mm move (one fast tick)
constexpr const char* kSuzanne = "/usr/share/assimp/models/BLEND/Suzanne_248.blend";

// Both clocks per query: wall time (what the haptic thread waits, preemption included) and this
// thread's CPU time (the query's own cost: on a shared, oversubscribed machine the wall-time
// tail is mostly time spent waiting for a core).
struct Timer {
  std::vector<double> wall_us, cpu_us;
  Timer() { wall_us.reserve(1 << 20); cpu_us.reserve(1 << 20); }
  static double cpu_now_us() {
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) * 1e6 + static_cast<double>(ts.tv_nsec) * 1e-3;
  }
  template <class F>
  auto time(F&& f) {
    const double c0 = cpu_now_us();
    const auto t0 = std::chrono::steady_clock::now();
    auto r = f();
    const auto t1 = std::chrono::steady_clock::now();
    const double c1 = cpu_now_us();
    if (wall_us.size() < wall_us.capacity()) {
      wall_us.push_back(std::chrono::duration<double, std::micro>(t1 - t0).count());
      cpu_us.push_back(c1 - c0);
    }
    return r;
  }
  void report(benchmark::State& state) const {
    const Percentiles w = percentiles(wall_us), c = percentiles(cpu_us);
    state.counters["p50_us"] = w.p50;
    state.counters["p99_us"] = w.p99;
    state.counters["cpu_p50_us"] = c.p50;
    state.counters["cpu_p99_us"] = c.p99;
  }
};

struct Fixture {
  MeshBvh bvh;
  std::vector<glm::dvec3> points;  // query points near the surface
  bool ok = false;
};

// Points within `spread` mm of random surface points: where a proxy is when it matters.
std::vector<glm::dvec3> near_surface(const Mesh& m, double spread, int n) {
  std::mt19937 rng(1);
  std::uniform_int_distribution<std::size_t> tri(0, m.indices.size() / 3 - 1);
  std::uniform_real_distribution<double> u(0.0, 1.0), s(-spread, spread);
  std::vector<glm::dvec3> out;
  for (int i = 0; i < n; ++i) {
    const std::size_t t = tri(rng);
    double a = u(rng), b = u(rng);
    if (a + b > 1.0) { a = 1.0 - a; b = 1.0 - b; }
    const glm::dvec3 p0(m.positions[m.indices[3 * t]]), p1(m.positions[m.indices[3 * t + 1]]),
        p2(m.positions[m.indices[3 * t + 2]]);
    out.push_back(p0 + a * (p1 - p0) + b * (p2 - p0) + glm::dvec3(s(rng), s(rng), s(rng)));
  }
  return out;
}

Fixture make(const Mesh& m) {
  Fixture f;
  f.ok = f.bvh.add_mesh(m).ok() && f.bvh.commit().ok();
  f.points = near_surface(m, kProbeRadiusMm + 2.0, 4096);
  return f;
}

Fixture& suzanne() {
  static Fixture f = [] {
    auto m = load_mesh_file(kSuzanne);
    if (!m) return Fixture{};
    transform_mesh(*m, 22.0, glm::dvec3(0.0), glm::dvec3(0.0));  // as scenes/table5_1_monkey_head.toml
    return make(*m);
  }();
  return f;
}

Fixture& torus100k() {
  // 320 segments x 160 around the tube x 2 = 102 400 triangles, R = 40 mm, r = 15 mm.
  static Fixture f = make(mesh_detail::make_torus(40.0, 15.0, 320));
  return f;
}

template <class Query>
void run(benchmark::State& state, Fixture& f, Query query) {
  if (!f.ok) { state.SkipWithError("mesh not available (assimp-testmodels)"); return; }
  Timer timer;
  double visited = 0.0;
  std::size_t i = 0;
  for (auto _ : state) {
    const glm::dvec3& p = f.points[i++ % f.points.size()];
    const std::uint32_t v = timer.time([&] { return query(p); });
    benchmark::DoNotOptimize(v);
    visited += v;
  }
  timer.report(state);
  state.counters["local_tris"] = visited / static_cast<double>(std::max<std::size_t>(i, 1));
  state.counters["overall_tris"] = static_cast<double>(f.bvh.triangle_count());
}

void BM_ClosestLocal(benchmark::State& state, Fixture& (*fixture)()) {
  Fixture& f = fixture();
  run(state, f, [&](const glm::dvec3& p) { return f.bvh.closest(p, kQueryRadiusMm).visited; });
}
// The haptic loop's pattern: consecutive queries 0.05 mm apart (50 mm/s at 1 kHz), along 5 mm
// strokes that start at the query points above (so they stay near the surface), each query
// starting from the previous hit (MeshBvh::closest's hint).
void BM_ClosestCoherent(benchmark::State& state, Fixture& (*fixture)()) {
  Fixture& f = fixture();
  MeshHit last;
  std::size_t k = 0;
  double along = 0.0;
  run(state, f, [&](const glm::dvec3&) {
    const glm::dvec3 a = f.points[k % f.points.size()], b = f.points[(k + 1) % f.points.size()];
    const glm::dvec3 dir = glm::normalize(b - a + glm::dvec3(1e-9, 0.0, 0.0));
    const glm::dvec3 p = a + along * dir;
    if ((along += 0.05) > 5.0) { along = 0.0; ++k; }
    last = f.bvh.closest(p, kQueryRadiusMm, &last);
    return last.visited;
  });
}
void BM_ClosestUnlimited(benchmark::State& state, Fixture& (*fixture)()) {
  Fixture& f = fixture();
  run(state, f, [&](const glm::dvec3& p) { return f.bvh.closest(p, 1e9).visited; });
}
void BM_ClosestBruteForce(benchmark::State& state, Fixture& (*fixture)()) {
  Fixture& f = fixture();
  run(state, f, [&](const glm::dvec3& p) { return f.bvh.closest_brute_force(p).visited; });
}

// A whole god-object move (several queries) on the Suzanne scene: the device circles 30 mm
// around the muzzle, as `bench-haptics` drives it, 1 ms per move at 1 turn/s.
void BM_GodObjectMoveSuzanne(benchmark::State& state) {
  if (!std::filesystem::exists(kSuzanne)) { state.SkipWithError("assimp-testmodels not installed"); return; }
  Scene sc;
  sc.probe.radius_mm = kProbeRadiusMm;
  sc.materials.emplace_back();
  Surface s;
  s.type = SurfaceType::kMesh;
  s.mesh_file = kSuzanne;
  s.scale = 22.0;
  sc.surfaces.push_back(s);
  auto scene = HapticScene::build(sc);
  if (!scene) { state.SkipWithError(scene.error().message.c_str()); return; }
  GodObject god(scene.value());
  const glm::dvec3 center{0.0, -20.9, -8.4};  // scenes/table5_1_monkey_head.toml's probe
  Timer timer;
  double facets = 0.0, contact = 0.0;
  std::size_t i = 0;
  for (auto _ : state) {
    const double a = 2.0 * 3.14159265358979323846 * static_cast<double>(i++ % 1000) / 1000.0;
    const glm::dvec3 x = center + 30.0 * glm::dvec3(std::cos(a), std::sin(a), 0.0);
    const ProxyStep st = timer.time([&] { return god.move(x); });
    facets += st.facets_visited;
    contact += st.in_contact ? 1.0 : 0.0;
  }
  timer.report(state);
  state.counters["local_tris"] = facets / static_cast<double>(std::max<std::size_t>(i, 1));
  state.counters["contact_frac"] = contact / static_cast<double>(std::max<std::size_t>(i, 1));
  state.counters["overall_tris"] = static_cast<double>(scene->triangle_count());
}

BENCHMARK_CAPTURE(BM_ClosestLocal, suzanne, &suzanne);
BENCHMARK_CAPTURE(BM_ClosestLocal, torus_102k, &torus100k);
BENCHMARK_CAPTURE(BM_ClosestCoherent, suzanne, &suzanne);
BENCHMARK_CAPTURE(BM_ClosestCoherent, torus_102k, &torus100k);
BENCHMARK_CAPTURE(BM_ClosestUnlimited, suzanne, &suzanne);
BENCHMARK_CAPTURE(BM_ClosestUnlimited, torus_102k, &torus100k);
BENCHMARK_CAPTURE(BM_ClosestBruteForce, suzanne, &suzanne);
BENCHMARK_CAPTURE(BM_ClosestBruteForce, torus_102k, &torus100k)->Iterations(2000);
BENCHMARK(BM_GodObjectMoveSuzanne);

}  // namespace
}  // namespace ps::world

BENCHMARK_MAIN();
