// Where the window's overlays go (`pseudoshadow run`): the readouts box, the help box and the
// docked parameter panel are placed around the pseudo-shadow, never over it when there is room.
// Pure geometry on window pixels (no GL, no ImGui), so it is unit tested on its own
// (tests/app/ui_layout_test.cpp); app/window/hud.cpp draws what it decides.
//
// Coordinates: window pixels as ImGui and X screenshots use them, origin at the top-left
// corner, y down. Rectangles are half-open: [x0, x1) x [y0, y1).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "image/image.h"

namespace ps {

struct UiRect {
  float x0 = 0.f, y0 = 0.f, x1 = 0.f, y1 = 0.f;
  static UiRect at(float x, float y, float w, float h) { return {x, y, x + w, y + h}; }
  float width() const { return x1 - x0; }
  float height() const { return y1 - y0; }
  bool empty() const { return !(x1 > x0 && y1 > y0); }
};
bool intersects(const UiRect& a, const UiRect& b);
float overlap_area(const UiRect& a, const UiRect& b);
UiRect grown(const UiRect& r, float by);

// A pixel counts as shadowed when its pseudo-shadow intensity is above 1/255: the smallest
// darkening that can change an 8-bit pixel of a white surface. Anything fainter cannot be seen,
// anything stronger must not be covered.
constexpr float kShadowVisibleIntensity = 1.0f / 255.0f;

// The pseudo-shadow as the frame drew it, measured on the renderer's AOVs (image size, top
// row first) and scaled to a window of window_w x window_h pixels.
struct ShadowMeasure {
  std::optional<UiRect> bbox;              // bounding box of the shadowed pixels; none: no shadow
  std::optional<double> min_distance_mm;   // smallest probe-surface distance d over them (if read)
  std::uint32_t pixels = 0;                // shadowed pixels (image pixels, not window pixels)
  // The centre of the shadow's core (window pixels): the centroid of its pixels within
  // kShadowCoreShare of its darkest, around the point under the probe. The box's centre is no
  // centre: seen in perspective the near half of the shadow looks larger (23 px below the
  // pointer on the Table 5.1 samples, 31 mm from the camera).
  std::optional<std::pair<float, float>> core;
};
inline constexpr float kShadowCoreShare = 0.9f;
// `intensity`: the intensity AOV (1 channel); `distance`: the distance AOV (1 channel, NaN
// where no probe is above the pixel; the same size) or null: no min_distance_mm.
ShadowMeasure measure_shadow(const Image& intensity, const Image* distance, int window_w, int window_h);

enum class PanelSide { kRight, kLeft };
enum class Corner { kTopLeft, kTopRight, kBottomLeft, kBottomRight };

// What the last frame chose: kept while it still leaves the shadow free, so the boxes do not
// jump from side to side while the probe moves in the middle.
struct UiPlacement {
  PanelSide panel_side = PanelSide::kRight;
  Corner hud_corner = Corner::kTopLeft;
  bool panel_placed = false;  // the panel has been laid out since it was last opened
  // Since when (UiLayoutInput::now_s) the other side has been wanted without a break; none: it is not.
  std::optional<double> flip_wanted_since_s;
  // When (UiLayoutInput::now_s) the pointer was last over the panel; none: not since it opened.
  std::optional<double> pointer_on_panel_s;
  // The panel sliding to panel_side (kPanelSlideS): since when, and the left edge it set out
  // from (window pixels); none: it rests on its side.
  std::optional<double> slide_since_s;
  float slide_from_x = 0.f;
};

// The panel changes sides only while the pointer is at least this far from both strips, px:
// the shadow (under the pointer, ~190 px wide at 1280 x 800) reaches a strip before the pointer
// does, and a panel that fled from it could never be reached. (Half the panel's width, 77 px at
// 512 px, let it change side under a pointer resting 80 px from it.)
constexpr float kPanelPointerKeepPx = 150.f;
// ... nor within this long of the pointer being over it, s: a person who left the panel for the
// scene a moment ago comes back to it where it was.
constexpr double kPanelPointerMemoryS = 2.0;
// ... and only once the other side has been wanted for this long without a break: a pointer
// that leaves the panel for the scene and comes back (a flick, a glance) finds it where it was,
// though the shadow under the pointer was under the panel a frame ago. A shadow that really
// rests under the panel sends it over within a second.
constexpr double kPanelFlipDwellS = 0.75;
// A panel that changes side slides across in this long, s, eased in and out (smoothstep): one
// frame's jump across the window reads as a new window, a slide as the same panel moving; 0.3 s
// is 3-9 frames at the window's 10-30 frames a second, short enough not to hold up a pointer
// going for it. It starts where the panel is drawn, so a slide turned back midway stays continuous.
constexpr double kPanelSlideS = 0.3;

struct UiLayoutInput {
  float width = 0.f, height = 0.f;  // window
  std::optional<UiRect> shadow;     // from measure_shadow
  bool panel = false;               // the parameter panel is shown
  float panel_width = 0.f;          // see panel_width_for()
  float panel_height = 0.f;         // the window's height, or its title bar when collapsed
  float hud_w = 0.f, hud_h = 0.f;   // the readouts box
  bool help = false;                // the help box is shown
  float help_w = 0.f, help_h = 0.f;
  // The help in one narrow column (0: none): used where the wide one would cover a button or
  // the shadow and the narrow one covers less (the control panel's buttons fill a square).
  float help_narrow_w = 0.f, help_narrow_h = 0.f;
  std::vector<UiRect> buttons;      // the scene's buttons on screen (app/window/button_overlay.h): never covered by text
  std::optional<std::pair<float, float>> pointer;  // the mouse in the window; none: outside it
  double now_s = 0.0;               // a clock in seconds (kPanelFlipDwellS)
  UiPlacement last;
};

struct UiLayout {
  std::optional<UiRect> panel, help;
  std::optional<UiRect> hud;  // none: no room beside the help, shown again once it hides
  bool help_narrow = false;   // the help is the narrow one
  UiPlacement placement;
};

// Panel: a strip along the right edge (full height), or along the left edge when the shadow
// would be under it; if both would cover it, the side that covers less than half of what the
// other does, else the last frame's side. Once shown it keeps its side while the pointer is in
// the window near either strip (kPanelPointerKeepPx) or was over it lately (kPanelPointerMemoryS),
// so the mouse can always reach it, and changes side only after wanting to for kPanelFlipDwellS,
// sliding across (kPanelSlideS); the boxes take their places beside the side it goes to from the
// start of the slide. Readouts: the corner of the rest of the window that keeps clear of the
// shadow and the buttons, the farthest from the shadow first. Help: bottom or top centre of the
// rest, else a corner, clear of the shadow, the buttons and the readouts; when the two cannot
// both stay clear, the readouts are left out while the help shows. Text never goes over a button
// while a place clear of every button exists.
UiLayout layout_ui(const UiLayoutInput& in);

// 30 % of the window, but at least 150 px (the longest parameter name, 19 characters of the
// 7-pixel default font, plus padding and scrollbar) and at most 360 px.
float panel_width_for(float window_width);

// One frame's rectangles for `run --ui-report`.
struct UiFrameReport {
  std::uint64_t frame = 0;
  std::optional<UiRect> shadow, hud, help, panel;
  std::vector<UiRect> buttons;  // the scene's buttons on screen (app/window/button_overlay.h)
};
// {"frames": [{"frame": 0, "shadow": [x0, y0, x1, y1] or null, "hud": ..., "help": ...,
//  "panel": ..., "buttons": [[x0, y0, x1, y1], ...]}, ...], "window": [w, h]} (the window's size
// last: a streamed report, app/window/readouts_log.h UiReportLog, knows it only at the end).
std::string ui_report_json(int window_w, int window_h, const std::vector<UiFrameReport>& frames);
// Its pieces: the text before the first frame, the frame numbered `index` (from 0) appended with
// the separator before it, the text after the last.
inline constexpr const char* kUiReportHead = "{\n  \"frames\": [";
void append_ui_frame(std::string& out, std::uint64_t index, const UiFrameReport& f);
std::string ui_report_tail(int window_w, int window_h);

}  // namespace ps
