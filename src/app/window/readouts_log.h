// `run --readouts-log FILE`: one JSON line per window frame with what the readouts say (one
// state machine, app/window/readout_state.h) and the positions behind it, for experimenters and for the
// window tests (tests/window). Fields (docs/window.md, "run --readouts-log"): frame, t_s, scene,
// state, distance_mm (null out of reach, 0 touching), pressed_mm, held_mm (the part of it the surface
// holds: without the fields' push), penetration_mm, buried_mm, contact,
// force_n, view_offset_mm, view_turn_deg (how far a rolling 4D surface has turned the view from
// where the scene started: 0 for every other scene), hand_mm, proxy_mm, button ({index, depth_mm, travel_mm} or null),
// flags (names on, or null when the scene has none), keys (key presses handled this frame),
// haptic_hz and jitter_p99_us (the haptic loop over the last second: what tools/soak.sh follows),
// dent_mm (the deepest dent of a deformable surface as drawn; null when the scene has none),
// pointer_px (the cursor in window pixels; null outside the window) and shadow_px (the centre of
// the pseudo-shadow's bounding box in window pixels, the measure --ui-report gives; null: none),
// surface_scale (the scale the frame's surface pass drew at: below 1 while the view moves,
// docs/adaptive.md) and view_moved (the frame's camera differed from the last frame's).
#pragma once

#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/window/readout_state.h"
#include "app/window/ui_layout.h"
#include "core/file_io.h"
#include "core/result.h"

namespace ps {

struct ReadoutsFrame {
  std::uint64_t frame = 0;
  double t_s = 0.0;                 // session time of the haptic state drawn
  std::string scene;                // the scene file's name
  ProbeReadout probe;
  std::optional<double> distance_mm;  // the shadow's smallest distance (none: no shadow)
  double penetration_mm = 0.0;      // the frame's largest penetration (render side)
  // How deep the proxy sphere sits inside the haptic geometry, mm (0: free). The render side's
  // penetration is measured along the reference normal per pixel, so a probe beside a steep
  // surface reads as inside it; this one is the proxy's own.
  double buried_mm = 0.0;
  double force_n = 0.0;             // |force on the hand|
  glm::dvec3 view_offset_mm{0.0}, hand_mm{0.0}, proxy_mm{0.0};
  double view_turn_deg = 0.0;       // view_turn_deg(HapticState::view_rotation)
  int button = -1;                  // pressed button (-1: none), its depth and travel
  double button_depth_mm = 0.0, button_travel_mm = 0.0;
  std::optional<std::vector<std::string>> flags;  // the flags on; none: the scene has no flags
  int keys = 0;                     // key presses handled this frame
  double haptic_hz = 0.0;           // the haptic loop's rate over the last second
  double jitter_p99_us = 0.0;       // |period - nominal|, p99 over the last second
  std::optional<double> dent_mm;    // largest vertex displacement of the deformable surfaces
  std::optional<glm::dvec2> pointer_px, shadow_px;  // window pixels (origin top left, y down)
  double surface_scale = 1.0;       // FrameStats::surface_scale
  bool view_moved = false;          // FrameStats::view_moved
};

// The angle of the rotation `r`, degrees (0 at identity, up to 180), from its sine (the
// antisymmetric part) and cosine (the trace) together: exact near 0, where acos of the trace
// alone loses half the digits.
double view_turn_deg(const glm::dmat3& r);

// The frame as one JSON line (no newline); numbers with up to 4 decimals (0.1 um: far below any
// tolerance a reader would use).
std::string readouts_json_line(const ReadoutsFrame& f);

// `run --ui-report FILE`: every frame's UI rectangles (app/window/ui_layout.h), streamed to a
// hidden file beside FILE as the frames come and published as FILE at close(), with the window's
// size: the same bytes as ui_report_json of the whole run, FILE whole or absent. Held in memory
// instead, an hour at 30 frames a second was 27 MiB (about 250 bytes a frame: the tour soak's
// RSS grew by it, docs/hardening.md). A write error is kept and returned by close(); the frames
// after it are dropped. Destroyed unclosed (a failed run), nothing is published.
class UiReportLog {
 public:
  Status open(const std::string& path);
  void add(const UiFrameReport& f);
  Status close(int window_w, int window_h);
  std::uint64_t frames() const { return frames_; }

 private:
  Status flush();
  std::optional<TempFile> file_;
  std::string pending_;  // written in blocks of kBlockBytes
  std::uint64_t frames_ = 0;
  Status failed_ = ok_status();
  static constexpr std::size_t kBlockBytes = 64 * 1024;
};

class ReadoutsLog {
 public:
  ReadoutsLog() = default;
  ~ReadoutsLog();
  ReadoutsLog(const ReadoutsLog&) = delete;
  ReadoutsLog& operator=(const ReadoutsLog&) = delete;
  // Creates (truncates) `path`; an error names it.
  Status open(const std::string& path);
  bool is_open() const { return file_ != nullptr; }
  // Appends one line and flushes it (a session killed by a test's timeout keeps its frames).
  Status write(const ReadoutsFrame& f);
  Status close();

 private:
  std::FILE* file_ = nullptr;
  std::string path_;
};

}  // namespace ps
