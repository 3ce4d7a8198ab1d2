// `pseudoshadow bench --moving`: whole frames against adaptive ones while the view moves.
#include "app/bench/bench_moving.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>

#include <glm/gtc/matrix_transform.hpp>

#include "prepare/prepare.h"
#include "render/adaptive_scale.h"
#include "render/renderer.h"
#include "scene/scene_io.h"

namespace ps::bench {

namespace {

using Clock = std::chrono::steady_clock;

double ms_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const auto i = static_cast<size_t>(std::lround(q * static_cast<double>(v.size() - 1)));
  return v[std::min(i, v.size() - 1)];
}

// A scripted motion: the frame input of moving frame i (60 frames a second) on `scene`.
struct Motion {
  const char* name;
  const char* scene;  // under the shipped scenes; empty: the embedded default
  FrameInput (*input)(const Scene& scene, int i);
};

// 90 degrees a second around the target, about the camera's up: a mouse drag's orbit.
FrameInput orbit_input(const Scene& s, int i) {
  FrameInput in = probe_frame_input(s.probe.position, s.probe.velocity);
  in.camera = orbited(s.camera, 1.5 * i);
  return in;
}

// Field's view travelling along x at 150 mm/s (10 mm past a wall, docs/universe.md), the probe
// carried with it as the hand stays in its box.
FrameInput travel_input(const Scene& s, int i) {
  const glm::dvec3 offset(2.5 * i, 0.0, 0.0);
  FrameInput in = probe_frame_input(s.probe.position + offset, s.probe.velocity);
  in.view = ViewPose{offset, glm::dmat3(1.0)};
  return in;
}

// The rolling torus's view turning about the vertical through the camera's target, 90 degrees a
// second, the probe turned with it (it stays where the hand holds it in the workspace).
FrameInput turn_input(const Scene& s, int i) {
  const glm::dmat3 r(glm::rotate(glm::dmat4(1.0), glm::radians(1.5 * i), glm::dvec3(0.0, 0.0, 1.0)));
  const glm::dvec3 t = s.camera.target - r * s.camera.target;
  FrameInput in = probe_frame_input(r * s.probe.position + t, s.probe.velocity);
  in.view = ViewPose{t, r};
  return in;
}

constexpr Motion kMotions[] = {{"orbit", "", orbit_input},
                               {"travel", "universe/field.toml", travel_input},
                               {"turn", "fourd/flat_torus_rolling.toml", turn_input}};

Result<Scene> motion_scene(const Motion& m, glm::ivec2 size) {
  const std::string set = "render.size=[" + std::to_string(size.x) + "," + std::to_string(size.y) + "]";
  if (*m.scene == '\0') return parse_scene(default_scene_text(), "<embedded default>", default_scene_base_dir(), {set});
  return load_scene(default_scene_base_dir() + "/" + m.scene, {set});
}

// The two renderers of one case: whole frames, and adaptive ones with their controller.
struct Pair {
  std::unique_ptr<Renderer> full, adaptive;
  AdaptiveScale control;
  // The adaptive session's clock, ms: its own frames' wall times only (the whole renderer's frames
  // drawn in between are the bench's, not the session's), so the rest delay is a session's.
  double clock_ms = 0.0;
  std::map<std::string, std::vector<double>> full_passes, adaptive_passes;
};

// One frame of each, the whole one first; returns their wall times (glFinish per pass: the
// frame is drawn when render() returns).
Result<std::pair<double, double>> frame_pair(Pair& p, const FrameInput& in, bool record) {
  auto a0 = Clock::now();
  if (auto s = p.full->render(in); !s) return s.error();
  const double full_ms = ms_between(a0, Clock::now());
  p.adaptive->set_surface_scale(p.control.next(p.clock_ms));
  a0 = Clock::now();
  if (auto s = p.adaptive->render(in); !s) return s.error();
  const double adaptive_ms = ms_between(a0, Clock::now());
  p.clock_ms += adaptive_ms;
  const FrameStats& st = p.adaptive->stats();
  p.control.frame(p.clock_ms, adaptive_ms, st.surface_scale, st.view_moved, st.measures_full_redraw());
  if (record) {
    for (const auto& [name, ms] : p.full->stats().timings_ms) p.full_passes[name].push_back(ms);
    for (const auto& [name, ms] : st.timings_ms) p.adaptive_passes[name].push_back(ms);
  }
  return std::make_pair(full_ms, adaptive_ms);
}

// Colour RMS over every channel, and the largest luminance difference along the row through the
// middle of the pseudo-shadow (the whole frame's intensity AOV > 0), 16 pixels beyond each side.
Status image_error(const Renderer& full, const Renderer& adaptive, double& rms, double& profile_max) {
  const Image a = full.read_color(), b = adaptive.read_color();
  double sum = 0.0;
  for (size_t i = 0; i < a.pixels.size(); ++i) sum += std::pow(static_cast<double>(a.pixels[i]) - b.pixels[i], 2);
  rms = 255.0 * std::sqrt(sum / static_cast<double>(std::max<size_t>(a.pixels.size(), 1)));
  auto intensity = full.read_aov(Aov::kIntensity);
  if (!intensity) return intensity.error();
  int x0 = a.width, x1 = -1, y0 = a.height, y1 = -1;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      if (intensity->at(x, y, 0) > 0.0f) x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  profile_max = 0.0;
  if (x1 < 0) return ok_status();
  const int y = (y0 + y1) / 2;
  for (int x = std::max(0, x0 - 16); x <= std::min(a.width - 1, x1 + 16); ++x) {
    double la = 0.0, lb = 0.0;
    for (int c = 0; c < 3; ++c) la += a.at(x, y, c) / 3.0, lb += b.at(x, y, c) / 3.0;
    profile_max = std::max(profile_max, 255.0 * std::abs(la - lb));
  }
  return ok_status();
}

std::vector<std::pair<std::string, double>> pass_medians(const std::map<std::string, std::vector<double>>& passes) {
  std::vector<std::pair<std::string, double>> out;
  for (const auto& [name, v] : passes) out.emplace_back(name, percentile(v, 0.5));
  return out;
}

// After the motion: frames of the last view until the adaptive one is whole again (rest_ms),
// then three more of each and the last compared bit for bit.
Status rest(Pair& p, const FrameInput& last, MovingRow& row) {
  const double stopped_ms = p.clock_ms;
  for (int i = 0; i < 60; ++i) {
    if (auto f = frame_pair(p, last, false); !f) return f.error();
    if (p.adaptive->stats().surface_scale >= 1.0) {
      row.rest_ms = p.clock_ms - stopped_ms;
      break;
    }
  }
  for (int i = 0; i < 3; ++i)
    if (auto f = frame_pair(p, last, false); !f) return f.error();
  row.rest_equal = p.full->read_color().pixels == p.adaptive->read_color().pixels;
  return ok_status();
}

constexpr int kWarm = 5;  // moving frames first drawn untimed: shader builds, caches

// The timed moving frames, and every error_every-th one's image error (read outside the timing).
Status moving_frames(const MovingOptions& o, const Motion& m, const Scene& scene, Pair& p, MovingRow& row) {
  double rms_sum = 0.0;
  int rms_n = 0;
  for (int i = 0; i < kWarm + o.frames; ++i) {
    auto f = frame_pair(p, m.input(scene, i), i >= kWarm);
    if (!f) return f.error();
    if (i < kWarm) continue;
    row.full_frames.push_back(f->first);
    row.adaptive_frames.push_back(f->second);
    row.scales.push_back(p.adaptive->stats().surface_scale);
    if ((i - kWarm) % std::max(o.error_every, 1) == 0) {
      double rms = 0.0, profile = 0.0;
      if (Status s = image_error(*p.full, *p.adaptive, rms, profile); !s) return s;
      rms_sum += rms, ++rms_n;
      row.profile_max_levels = std::max(row.profile_max_levels, profile);
    }
  }
  row.rms_levels = rms_n ? rms_sum / rms_n : 0.0;
  return ok_status();
}

Result<MovingRow> run_case(const MovingOptions& o, const Motion& m, glm::ivec2 size) {
  auto scene = motion_scene(m, size);
  if (!scene) return scene.error();
  Pair p;
  auto full = open_renderer(scene.value(), {});
  if (!full) return full.error();
  p.full = std::move(full.value());
  RendererOptions share;
  share.reuse_tiles_from = p.full.get();
  auto adaptive = open_renderer(scene.value(), share);
  if (!adaptive) return adaptive.error();
  p.adaptive = std::move(adaptive.value());
  AdaptiveScaleParams params;
  params.budget_ms = o.budget_ms;
  p.control = AdaptiveScale(params);
  MovingRow row;
  row.motion = m.name;
  row.scene = *m.scene ? m.scene : "default.toml";
  row.size = size;
  if (Status s = moving_frames(o, m, scene.value(), p, row); !s) return s.error();
  if (Status s = rest(p, m.input(scene.value(), kWarm + o.frames - 1), row); !s) return s.error();
  row.full_p50_ms = percentile(row.full_frames, 0.5), row.full_p99_ms = percentile(row.full_frames, 0.99);
  row.adaptive_p50_ms = percentile(row.adaptive_frames, 0.5), row.adaptive_p99_ms = percentile(row.adaptive_frames, 0.99);
  row.scale_min = *std::min_element(row.scales.begin(), row.scales.end());
  row.scale_median = percentile(row.scales, 0.5);
  row.full_passes = pass_medians(p.full_passes);
  row.adaptive_passes = pass_medians(p.adaptive_passes);
  return row;
}

}  // namespace

Camera orbited(const Camera& camera, double degrees) {
  Camera c = camera;
  const glm::dmat4 turn = glm::rotate(glm::dmat4(1.0), glm::radians(degrees), camera.up);
  c.position = camera.target + glm::dvec3(turn * glm::dvec4(camera.position - camera.target, 0.0));
  return c;
}

Result<std::vector<MovingRow>> run_moving(const MovingOptions& o) {
  std::vector<MovingRow> rows;
  for (const glm::ivec2 size : o.sizes)
    for (const Motion& m : kMotions) {
      if (o.progress) o.progress(std::string("moving: ") + m.name + " at " + std::to_string(size.x) + "x" + std::to_string(size.y) + " ...");
      auto row = run_case(o, m, size);
      if (!row) return row.error();
      rows.push_back(std::move(row.value()));
    }
  return rows;
}

namespace {

std::string fmt(const char* f, double a) {
  char b[64];
  std::snprintf(b, sizeof b, f, a);
  return b;
}

std::string size_name(glm::ivec2 s) { return std::to_string(s.x) + "x" + std::to_string(s.y); }

std::string passes_text(const std::vector<std::pair<std::string, double>>& passes) {
  std::string t;
  for (const auto& [name, ms] : passes) t += (t.empty() ? "" : ", ") + name + " " + fmt("%.2f", ms);
  return t;
}

}  // namespace

std::string moving_markdown(const std::vector<MovingRow>& rows, const MovingOptions& o) {
  std::string md = "| motion | size | whole p50 / p99 ms | adaptive p50 / p99 ms | p50 ratio | scale median (min) "
                   "| rest -> whole frame ms | rest frame equal | RMS error (levels) | shadow row max diff (levels) |\n"
                   "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
  for (const MovingRow& r : rows)
    md += "| " + r.motion + " (" + r.scene + ") | " + size_name(r.size) + " | " + fmt("%.1f", r.full_p50_ms) + " / " +
          fmt("%.1f", r.full_p99_ms) + " | " + fmt("%.1f", r.adaptive_p50_ms) + " / " + fmt("%.1f", r.adaptive_p99_ms) +
          " | " + fmt("%.2fx", r.full_p50_ms / std::max(r.adaptive_p50_ms, 1e-9)) + " | " + fmt("%.2f", r.scale_median) +
          " (" + fmt("%.2f", r.scale_min) + ") | " + fmt("%.1f", r.rest_ms) + " | " + (r.rest_equal ? "yes" : "NO") +
          " | " + fmt("%.2f", r.rms_levels) + " | " + fmt("%.1f", r.profile_max_levels) + " |\n";
  md += "\n" + std::to_string(o.frames) + " moving frames per row, budget " + fmt("%.1f", o.budget_ms) +
        " ms. Per-pass medians, ms (CPU wall, glFinish per pass):\n\n| motion | size | whole frames | adaptive frames |\n"
        "| --- | --- | --- | --- |\n";
  for (const MovingRow& r : rows)
    md += "| " + r.motion + " | " + size_name(r.size) + " | " + passes_text(r.full_passes) + " | " +
          passes_text(r.adaptive_passes) + " |\n";
  return md;
}

std::string moving_csv(const std::vector<MovingRow>& rows) {
  std::string csv = "motion,size,frame,full_ms,adaptive_ms,scale\n";
  for (const MovingRow& r : rows)
    for (size_t i = 0; i < r.full_frames.size(); ++i)
      csv += r.motion + "," + size_name(r.size) + "," + std::to_string(i) + "," + fmt("%.3f", r.full_frames[i]) + "," +
             fmt("%.3f", r.adaptive_frames[i]) + "," + fmt("%.2f", r.scales[i]) + "\n";
  return csv;
}

}  // namespace ps::bench
