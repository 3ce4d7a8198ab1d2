// `pseudoshadow bench-haptics`: the haptic loop on its real thread and clock while the
// renderer draws flat out on the main thread (headless), then rate, period jitter and the
// latency device sample -> finished frame. Numbers only; nothing here passes or fails.
#include <chrono>
#include <cmath>
#include <cstdio>

#include "app/cli/cli.h"
#include "app/cli/cli_groups.h"
#include "app/commands.h"
#include "app/session/session.h"
#include "gl/context.h"
#include "prepare/prepare.h"

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
}

int bench(const cli::Command& cmd, const BenchArgs& a) {
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
  const Status measured = measure(*renderer.value(), loop, a.seconds, latency_ms, frame_ms, facets);
  vib->close();
  if (!measured) return cmd.fail(measured.error());
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("bench-haptics: %s, %dx%d, %s, %s, haptic thread %s, %s frames\n", scene->path.c_str(),
              scene->render.width, scene->render.height, ctx.value()->renderer().c_str(), live->report().c_str(),
              loop.scheduling().c_str(), a.no_incremental ? "full" : "incremental");
  print_report(loop, elapsed, latency_ms, frame_ms, facets, haptic_scene.value());
  if (vib->active()) std::printf("%s\n", vib->summary().c_str());
  return cli::kExitOk;
}

}  // namespace

int run_bench_haptics(int argc, char** argv) {
  return cli::run_command<BenchArgs>(argc, argv, "bench-haptics", kDescription, declare, bench);
}

}  // namespace ps
