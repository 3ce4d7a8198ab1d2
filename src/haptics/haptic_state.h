// What the haptic thread shares with the rest of the program, besides its events: the state it
// publishes each tick (HapticState, Snapshot<HapticState>), and what the render thread publishes
// for it (LiveCharges, PublishedViewAxes). Plain values: a reader needs no other part of the loop.
#pragma once

#include <array>
#include <cstdint>

#include <glm/glm.hpp>

#include "devices/sanitizer.h"
#include "fourd/rolling.h"
#include "world/bodies.h"

namespace ps {

// Charges a person adds and removes while the loop runs (run's C / Shift+C), published by the
// render thread (Snapshot<LiveCharges>) and added to the scene's fields. Each has an id that is
// never reused, so the haptic thread can tell which ones came and went and say so in events.
struct LiveCharges {
  static constexpr int kMax = 16;
  int count = 0;
  std::array<std::uint32_t, kMax> id{};
  std::array<glm::dvec3, kMax> position{};
  std::array<double, kMax> charge_n_mm2{};
  double softening_mm = 2.0;
};

// The camera the renderer draws with, in the device's workspace (published once per frame by the
// render thread): the rolling manifold's screen centre and direction toward the viewer. Until
// one is published the loop uses the scene file's camera.
struct PublishedViewAxes {
  bool valid = false;
  fourd::ViewAxes axes;
};

struct HapticState {
  std::uint64_t tick = 0;
  double time_s = 0.0;               // session time of this tick
  std::int64_t sample_clock_ns = 0;  // clock time at which the device sample was read
  glm::dvec3 device_mm{0.0};         // sanitized raw device position
  glm::dvec3 position_mm{0.0};       // Kalman-filtered
  glm::dvec3 velocity_mm_s{0.0};     // Kalman-filtered; drives the texture amplitude
  glm::dvec3 proxy_mm{0.0};          // what the renderer shows
  glm::dvec3 force_n{0.0};
  double penetration_mm = 0.0;
  int contact_surface = -1;          // haptic scene: surface touched (Scene::surfaces index)
  std::uint32_t local_facets = 0;    // haptic scene: mesh triangles examined this tick
  std::uint32_t buttons = 0;
  glm::dvec3 field_force_n{0.0};     // haptic scene: fields + body springs on the probe this tick
  std::array<glm::dvec3, world::kMaxBodies> body_mm{};  // haptic scene: the bodies' centres
  int body_count = 0;
  int button_pressed = -1;           // haptic scene: the button the probe presses (-1: none)
  double button_depth_mm = 0.0;      // and how far it is in
  std::uint32_t flags = 0;           // haptic scene: bit i = Scene::flags[i], toggled by buttons
  // The number replace_scene() returned for the scene in use (0: the one given at construction):
  // a frame that draws a switched-to world waits for it, so it never shows the old world's probe.
  std::uint64_t scene_serial = 0;
  // haptic scene with [navigation]: how far the view has moved (the world position of the
  // workspace's origin). position_mm, device_mm and proxy_mm are world positions (the device's
  // own plus this offset); the renderer moves its camera by it.
  glm::dvec3 view_offset_mm{0.0};
  // haptic scene with a rolling fourd surface (fourd/rolling.h): the workspace also turns,
  // world = view_rotation * workspace + view_offset_mm; the renderer turns its camera with it.
  glm::dmat3 view_rotation{1.0};
  int roll_facet = -1;               // the rolling manifold's interest facet (-1: none)
  // haptic scene: the sheet of a surface embedded in 4D the proxy keeps to (docs/fourd.md):
  // its surface index (-1: none) and the 4D depth w there
  int sheet_surface = -1;
  double sheet_w4 = 0.0;
  bool have_sample = false, in_contact = false;
  // The proxy touches nothing but has not reached the hand yet (a jump larger than one tick's
  // approach, ForceResult::catching_up): its distance from the hand is no surface's hold.
  bool proxy_catching_up = false;
  double rate_hz = 0.0;              // over the last second
  double jitter_p99_us = 0.0;        // |period - nominal|, p99 over the last second
  SanitizerCounts rejected;
  // Falling behind (haptics/tick_schedule.h): stalls so far, ticks skipped so far, the last
  // stall's lateness, and the force's scale this tick (1 except while ramping after a stall).
  std::uint64_t stalls = 0;
  std::uint64_t skipped_ticks = 0;
  double last_stall_ms = 0.0;
  double force_scale = 1.0;
};

}  // namespace ps
