// `pseudoshadow bench-haptics`: the haptic loop on its real thread and clock while the
// renderer draws flat out on the main thread (headless), then rate, period jitter and the
// latency device sample -> finished frame. Numbers only; nothing here passes or fails.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "app/bench/bench_moving.h"
#include "app/cli/cli.h"
#include "app/cli/cli_groups.h"
#include "app/commands.h"
#include "app/session/session.h"
#include "gl/context.h"
#include "prepare/prepare.h"
#include "render/adaptive_scale.h"

namespace ps {

namespace {

std::vector<DeviceSample> circle_samples(const glm::dvec3& center, double seconds) {
  std::vector<DeviceSample> out;
  for (int i = 0; i <= static_cast<int>(seconds * 100.0); ++i) {  // 10 ms keyframes, interpolated
    const double t = i * 0.01, a = 2.0 * 3.14159265358979323846 * t;
    out.push_back({t, center + glm::dvec3(30.0 * std::cos(a), 30.0 * std::sin(a), 0.0), 0, true});
  }
  return out;
}

void print_report(const HapticLoop& loop, double seconds, const std::vector<double>& latency_ms,
                  const std::vector<double>& frame_ms, const std::vector<double>& facets,
                  const world::HapticScene& scene) {
  const auto& periods = loop.periods_us();
  std::vector<double> jitter;
  jitter.reserve(periods.size());
  for (double p : periods) jitter.push_back(std::abs(p - 1000.0));
  const Percentiles p = percentiles(periods), j = percentiles(jitter);
  const Percentiles l = percentiles(latency_ms), f = percentiles(frame_ms);
  std::printf("haptic loop: %zu ticks in %.2f s = %.1f Hz\n", periods.size() + 1, seconds,
              static_cast<double>(periods.size()) / seconds);
  std::printf("period us:   p50 %.1f  p99 %.1f  p99.9 %.1f  max %.1f  mean %.2f\n", p.p50, p.p99, p.p999, p.max, p.mean);
  std::printf("jitter us:   p50 %.1f  p99 %.1f  p99.9 %.1f  max %.1f\n", j.p50, j.p99, j.p999, j.max);
  const HapticState st = loop.state().read();  // falling behind: haptics/tick_schedule.h
  std::printf("late ticks:  stalls %llu (last %.1f ms), ticks skipped %llu\n", static_cast<unsigned long long>(st.stalls),
              st.last_stall_ms, static_cast<unsigned long long>(st.skipped_ticks));
  std::printf("frames:      %zu, ms p50 %.1f  p99 %.1f  max %.1f\n", f.count, f.p50, f.p99, f.max);
  std::printf("latency ms (device sample -> frame finished): p50 %.1f  p99 %.1f  max %.1f\n", l.p50, l.p99, l.max);
  // Hanson & Zhang, Table 1: polygons in the overall model vs those a tick examined (sampled once
  // per frame from the published state; ticks in free space count too).
  const Percentiles fc = percentiles(facets);
  std::printf("haptic scene: %zu analytic shapes, %zu triangles overall; local model per tick: mean %.1f  "
              "p99 %.0f  max %.0f triangles\n",
              scene.analytic_count(), scene.triangle_count(), fc.mean, fc.p99, fc.max);
}

// --orbit: the camera turns about its target (around its up) at `deg_per_s` of wall time, and
// the run alternates one-second phases of whole frames and of adaptive resolution (the window's
// AdaptiveScale, docs/adaptive.md), so that load from other processes hits both alike. Each
// phase's frames, latencies and haptic periods are reported apart: the haptic loop's period while
// the view moves, and the latency device sample -> frame finished, at both.
struct OrbitMode {
  const char* name = "";
  std::vector<double> frame_ms, latency_ms, scales, periods_us;
};

Status measure_orbit(Renderer& renderer, HapticLoop& loop, double seconds, double deg_per_s, double budget_ms,
                     OrbitMode (&modes)[2], std::vector<double>& facets) {
  using Clock = std::chrono::steady_clock;
  const Camera start = renderer.camera();
  AdaptiveScale control(AdaptiveScaleParams{.budget_ms = budget_ms});
  std::vector<std::pair<double, int>> phases;  // (start s since the loop's start, mode)
  const auto t0 = Clock::now();
  loop.start();
  for (std::uint64_t frame = 0;; ++frame) {
    const auto f0 = Clock::now();
    const double t = std::chrono::duration<double>(f0 - t0).count();
    if (t >= seconds) break;
    const int mode = static_cast<int>(t) % 2;  // 0 whole, 1 adaptive
    if (phases.empty() || phases.back().second != mode) phases.emplace_back(static_cast<int>(t), mode);
    renderer.set_surface_scale(mode == 1 ? control.next(t * 1e3) : SurfaceScale{});
    HapticState st;
    if (Status s = drive_frame(renderer, loop, frame, st, bench::orbited(start, deg_per_s * t)); !s) {
      loop.stop();
      return s;
    }
    const auto f1 = Clock::now();
    const double ms = std::chrono::duration<double, std::milli>(f1 - f0).count();
    const FrameStats& fs = renderer.stats();
    facets.push_back(st.local_facets);
    // Whole frames inform the controller too, as every frame does in the window.
    control.frame(t * 1e3 + ms, ms, fs.surface_scale, fs.view_moved, fs.measures_full_redraw());
    if (t - static_cast<int>(t) < 0.1) continue;  // a phase's first 0.1 s: the switch's frame settles
    modes[mode].frame_ms.push_back(ms);
    modes[mode].scales.push_back(fs.surface_scale);
    if (st.have_sample)
      modes[mode].latency_ms.push_back(static_cast<double>(f1.time_since_epoch().count() - st.sample_clock_ns) * 1e-6);
  }
  loop.stop();
  // Each period to the phase its tick ended in (the ticks' own clock: the running sum of periods
  // from the loop's start, which is within a tick of t0).
  double tick_s = 0.0;
  std::size_t phase = 0;
  for (double p : loop.periods_us()) {
    tick_s += p * 1e-6;
    while (phase + 1 < phases.size() && tick_s >= phases[phase + 1].first) ++phase;
    if (!phases.empty()) modes[phases[phase].second].periods_us.push_back(p);
  }
  return ok_status();
}

void print_orbit_report(const OrbitMode (&modes)[2], double deg_per_s, double budget_ms) {
  std::printf("orbit %.0f deg/s, phases of 1 s alternating whole and adaptive (budget %.1f ms); a phase's first 0.1 s "
              "not counted in frames:\n",
              deg_per_s, budget_ms);
  std::printf("| frames | count | frame p50 / p99 ms | latency p50 / p99 ms | scale median | haptic period p50 / p99 us | "
              "jitter p99 us |\n| --- | --- | --- | --- | --- | --- | --- |\n");
  for (const OrbitMode& m : modes) {
    std::vector<double> jitter;
    for (double p : m.periods_us) jitter.push_back(std::abs(p - 1000.0));
    const Percentiles f = percentiles(m.frame_ms), l = percentiles(m.latency_ms), s = percentiles(m.scales),
                      p = percentiles(m.periods_us), j = percentiles(jitter);
    std::printf("| %s | %zu | %.1f / %.1f | %.1f / %.1f | %.2f | %.1f / %.1f | %.1f |\n", m.name, f.count, f.p50, f.p99,
                l.p50, l.p99, s.p50, p.p50, p.p99, j.p99);
  }
}

// Renders flat out for `seconds` while the loop runs; per-frame time and latency in ms.
Status measure(Renderer& renderer, HapticLoop& loop, double seconds, std::vector<double>& latency_ms,
               std::vector<double>& frame_ms, std::vector<double>& facets) {
  const auto t0 = std::chrono::steady_clock::now();
  loop.start();
  for (std::uint64_t frame = 0;; ++frame) {
    const auto f0 = std::chrono::steady_clock::now();
    if (std::chrono::duration<double>(f0 - t0).count() >= seconds) break;
    HapticState st;
    if (Status s = drive_frame(renderer, loop, frame, st); !s) { loop.stop(); return s; }
    const auto f1 = std::chrono::steady_clock::now();  // render_frame ends with a synchronous readback
    frame_ms.push_back(std::chrono::duration<double, std::milli>(f1 - f0).count());
    facets.push_back(st.local_facets);
    if (st.have_sample) latency_ms.push_back(static_cast<double>(f1.time_since_epoch().count() - st.sample_clock_ns) * 1e-6);
  }
  loop.stop();
  return ok_status();
}

constexpr const char* kDescription =
    "Runs the 1 kHz haptic loop (synthetic device: a 30 mm circle around the probe's position, 1\n"
    "turn/s; the proxy collides with the scene's haptic geometry) while the renderer draws the scene\n"
    "flat out, and prints the loop rate, the period percentiles\n"
    "(p50/p99/p99.9/max), the jitter |period - 1 ms| and the latency device sample -> frame done.\n"
    "With --vibration-out the vibrotactile texture runs too, and its latency is reported.";

struct BenchArgs {
  cli::SceneArgs scene;
  cli::GlArgs gl_opts;
  double seconds = 5.0;
  double circle_z_mm = std::nan("");  // NaN: the scene probe's height
  int realtime = 0;
  int timer_slack_ns = -1;  // -1: the loop's default
  int wake_spin_us = -1;
  int slice_us = -1;
  cli::LiveLoopArgs live;
  bool no_incremental = false;  // RendererOptions::incremental off
  double orbit_deg_per_s = 0.0;   // 0: the camera stays
  double frame_budget_ms = 16.7;  // --orbit's adaptive phases (AdaptiveScaleParams::budget_ms)
};

void declare(cli::Command& cmd, BenchArgs& a) {
  CLI::App& app = cmd.app();
  cli::add_scene_options(app, a.scene);
  cli::add_image_options(app, a.scene);
  cli::add_positive(app, "--seconds", "S", a.seconds, 3600.0, "5", "duration (default 5)");
  cli::add_gl_options(app, a.gl_opts);
  cli::add_int(app, "--realtime", "PRIO", a.realtime, 1, 99,
               "run the haptic thread SCHED_FIFO at PRIO (1..99; needs CAP_SYS_NICE)");
  cli::add_int(app, "--timer-slack-ns", "NS", a.timer_slack_ns, 0, 1'000'000,
               "the haptic thread's timer slack (0 = the kernel's default, 50 us; default 1000)");
  cli::add_int(app, "--wake-spin-us", "US", a.wake_spin_us, 0, 900,
               "poll the clock for the last US microseconds before each tick (default 50)");
  cli::add_int(app, "--slice-us", "US", a.slice_us, 0, 100'000,
               "ask the scheduler for a US-microsecond slice for the haptic thread (0 = the kernel's; default 100)");
  app.add_option("--circle-z", a.circle_z_mm,
                 "height of the device's circle, mm (default: the scene probe's; below the probe radius over "
                 "a plane at z = 0 the probe strokes it: with --vibration-out, the texture's signal)")
      ->type_name("MM");
  cli::add_live_loop_options(app, a.live);
  app.add_flag("--no-incremental", a.no_incremental,
               "redraw every pixel of every frame (default: while the camera is still, only the shadow's rectangles)");
  cli::add_positive(app, "--orbit", "DEG_PER_S", a.orbit_deg_per_s, 3600.0, "90",
                    "turn the camera about its target at DEG_PER_S while measuring (a mouse drag's orbit: 90), in "
                    "one-second phases of whole frames and of adaptive resolution as the window draws (docs/adaptive.md); "
                    "reports each apart: frame time, latency, the scale, the haptic period");
  cli::add_positive(app, "--frame-budget", "MS", a.frame_budget_ms, 1000.0, "16.7",
                    "--orbit: the adaptive phases' frame budget (default 16.7, as `run`)");
}

int measure_and_report(const cli::Command& cmd, const BenchArgs& a) {
  auto scene = cli::load_scene_or_default(a.scene);
  if (!scene) return cmd.fail(scene.error(), cli::scene_exit_code(scene.error()));
  auto live = cli::apply_live_loop(a.live);  // before the context and the haptic thread
  if (!live) return cmd.usage_error(live.error());
  auto ctx = cli::open_context(a.gl_opts);
  if (!ctx) return cmd.fail(ctx.error());
  RendererOptions options;
  options.incremental = !a.no_incremental;
  auto renderer = open_renderer(scene.value(), options);
  if (!renderer) return cmd.fail(renderer.error());
  glm::dvec3 center = scene->probe.position;
  if (!std::isnan(a.circle_z_mm)) center.z = a.circle_z_mm;
  LogDevice device(circle_samples(center, a.seconds + 1.0), true, "synthetic circle");
  auto haptic_scene = world::HapticScene::build(scene.value());  // what the proxy collides with
  if (!haptic_scene) return cmd.fail(haptic_scene.error());
  SteadyClock clock;
  HapticLoopParams params;
  params.realtime_priority = a.realtime;
  if (a.timer_slack_ns >= 0) params.timer_slack_ns = a.timer_slack_ns;
  if (a.wake_spin_us >= 0) params.wake_spin_us = a.wake_spin_us;
  if (a.slice_us >= 0) params.sched_slice_us = a.slice_us;
  auto vib = std::unique_ptr<vibration::LiveVibration>();  // before the loop: it feeds it ticks
  HapticLoop loop(device, clock, params, &haptic_scene.value());
  vib = cli::open_live_vibration(a.live, scene.value(), loop);
  std::vector<double> latency_ms, frame_ms, facets;
  const auto t0 = std::chrono::steady_clock::now();
  vib->start();
  OrbitMode modes[2];
  modes[0].name = "whole", modes[1].name = "adaptive";
  const Status measured = a.orbit_deg_per_s > 0.0
                              ? measure_orbit(*renderer.value(), loop, a.seconds, a.orbit_deg_per_s, a.frame_budget_ms, modes, facets)
                              : measure(*renderer.value(), loop, a.seconds, latency_ms, frame_ms, facets);
  vib->close();
  if (!measured) return cmd.fail(measured.error());
  for (const OrbitMode& m : modes) {  // --orbit: the whole run's lines count both phases
    frame_ms.insert(frame_ms.end(), m.frame_ms.begin(), m.frame_ms.end());
    latency_ms.insert(latency_ms.end(), m.latency_ms.begin(), m.latency_ms.end());
  }
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("bench-haptics: %s, %dx%d, %s, %s, haptic thread %s, %s frames\n", scene->path.c_str(),
              scene->render.width, scene->render.height, ctx.value()->renderer().c_str(), live->report().c_str(),
              loop.scheduling().c_str(), a.no_incremental ? "full" : "incremental");
  print_report(loop, elapsed, latency_ms, frame_ms, facets, haptic_scene.value());
  if (a.orbit_deg_per_s > 0.0) print_orbit_report(modes, a.orbit_deg_per_s, a.frame_budget_ms);
  if (vib->active()) std::printf("%s\n", vib->summary().c_str());
  return cli::kExitOk;
}

}  // namespace

int run_bench_haptics(int argc, char** argv) {
  return cli::run_command<BenchArgs>(argc, argv, "bench-haptics", kDescription, declare, measure_and_report);
}

}  // namespace ps
