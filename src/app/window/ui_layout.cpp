#include "app/window/ui_layout.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>

namespace ps {

namespace {

constexpr float kEdgeMargin = 6.f;    // boxes keep this far from the window's edges
constexpr float kShadowMargin = 4.f;  // and this far from the shadow's bounding box

// The readouts' score: covering the shadow is worse than any overlap with the panel.
constexpr float kShadowWeight = 1e6f;

struct Candidate {
  UiRect rect;
  Corner corner = Corner::kTopLeft;  // for the readouts' corners
};

float centre_distance(const UiRect& a, const UiRect& b) {
  return std::hypot((a.x0 + a.x1 - b.x0 - b.x1) * 0.5f, (a.y0 + a.y1 - b.y0 - b.y1) * 0.5f);
}

// The candidate of lowest score; ties go to the earlier one (candidates come in preference order).
template <typename Score>
Candidate best(const std::vector<Candidate>& cands, Score score) {
  assert(!cands.empty() && "best: no candidate");
  size_t pick = 0;
  float pick_score = score(cands[0].rect);
  for (size_t i = 1; i < cands.size(); ++i) {
    const float s = score(cands[i].rect);
    if (s < pick_score) { pick = i; pick_score = s; }
  }
  return cands[pick];
}

UiRect panel_strip(const UiLayoutInput& in, PanelSide side) {
  const float x = side == PanelSide::kRight ? in.width - in.panel_width : 0.f;
  return UiRect::at(x, 0.f, in.panel_width, in.panel_height);
}

// The readouts' four corners of the free range [x0, x1), the current corner first, then the
// others from the farthest from the shadow to the nearest.
std::vector<Candidate> hud_corners(const UiLayoutInput& in, float x0, float x1, const UiRect& avoid) {
  const float w = in.hud_w, h = in.hud_h, l = x0 + kEdgeMargin, r = x1 - kEdgeMargin - w;
  const float t = kEdgeMargin, b = in.height - kEdgeMargin - h;
  std::vector<Candidate> c = {{UiRect::at(l, t, w, h), Corner::kTopLeft},
                              {UiRect::at(r, t, w, h), Corner::kTopRight},
                              {UiRect::at(l, b, w, h), Corner::kBottomLeft},
                              {UiRect::at(r, b, w, h), Corner::kBottomRight}};
  if (!avoid.empty())
    std::stable_sort(c.begin(), c.end(), [&](const Candidate& a, const Candidate& o) {
      return centre_distance(a.rect, avoid) > centre_distance(o.rect, avoid);
    });
  std::stable_partition(c.begin(), c.end(), [&](const Candidate& a) { return a.corner == in.last.hud_corner; });
  return c;
}

std::vector<Candidate> help_places(const UiLayoutInput& in, float x0, float x1, float w, float h) {
  const float cx = x0 + std::max(kEdgeMargin, std::round((x1 - x0 - w) * 0.5f));
  const float l = x0 + kEdgeMargin, r = x1 - kEdgeMargin - w;
  const float t = kEdgeMargin, b = in.height - kEdgeMargin - h;
  return {{UiRect::at(cx, b, w, h)}, {UiRect::at(cx, t, w, h)}, {UiRect::at(l, b, w, h)},
          {UiRect::at(r, b, w, h)},  {UiRect::at(l, t, w, h)},  {UiRect::at(r, t, w, h)}};
}

void append_rect(std::string& out, const char* key, const std::optional<UiRect>& r) {
  char buf[128];
  if (r) std::snprintf(buf, sizeof buf, ", \"%s\": [%.1f, %.1f, %.1f, %.1f]", key, r->x0, r->y0, r->x1, r->y1);
  else std::snprintf(buf, sizeof buf, ", \"%s\": null", key);
  out += buf;
}

}  // namespace

bool intersects(const UiRect& a, const UiRect& b) {
  return !a.empty() && !b.empty() && a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

float overlap_area(const UiRect& a, const UiRect& b) {
  if (!intersects(a, b)) return 0.f;
  return (std::min(a.x1, b.x1) - std::max(a.x0, b.x0)) * (std::min(a.y1, b.y1) - std::max(a.y0, b.y0));
}

UiRect grown(const UiRect& r, float by) { return {r.x0 - by, r.y0 - by, r.x1 + by, r.y1 + by}; }

namespace {

// The centroid of the shadow's core (pixels within kShadowCoreShare of its darkest), image pixels
// (pixel centres at i + 0.5), searched within [x0, x1] x [y0, y1].
std::pair<double, double> shadow_core(const Image& intensity, int x0, int y0, int x1, int y1) {
  float darkest = 0.f;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) darkest = std::max(darkest, intensity.at(x, y, 0));
  double sx = 0.0, sy = 0.0;
  int n = 0;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x)
      if (intensity.at(x, y, 0) >= kShadowCoreShare * darkest) {
        sx += x + 0.5;
        sy += y + 0.5;
        ++n;
      }
  return {sx / n, sy / n};  // n >= 1: the darkest pixel itself
}

}  // namespace

ShadowMeasure measure_shadow(const Image& intensity, const Image* distance, int window_w, int window_h) {
  assert(intensity.channels == 1 && (!distance || distance->channels == 1) && "measure_shadow: expects 1-channel AOVs");
  assert((!distance || (intensity.width == distance->width && intensity.height == distance->height)) &&
         "measure_shadow: the intensity and distance AOVs differ in size");
  ShadowMeasure m;
  int x0 = intensity.width, y0 = intensity.height, x1 = -1, y1 = -1;
  for (int y = 0; y < intensity.height; ++y)
    for (int x = 0; x < intensity.width; ++x) {
      if (!(intensity.at(x, y, 0) > kShadowVisibleIntensity)) continue;
      ++m.pixels;
      x0 = std::min(x0, x); x1 = std::max(x1, x);
      y0 = std::min(y0, y); y1 = std::max(y1, y);
      if (!distance) continue;
      const double d = distance->at(x, y, 0);
      if (!std::isnan(d) && (!m.min_distance_mm || d < *m.min_distance_mm)) m.min_distance_mm = d;
    }
  if (m.pixels == 0) return m;
  // Image pixel i covers window pixels [i * sx, (i + 1) * sx): the window may be scaled.
  const float sx = static_cast<float>(window_w) / intensity.width, sy = static_cast<float>(window_h) / intensity.height;
  m.bbox = UiRect{x0 * sx, y0 * sy, (x1 + 1) * sx, (y1 + 1) * sy};
  const auto [cx, cy] = shadow_core(intensity, x0, y0, x1, y1);
  m.core = std::make_pair(static_cast<float>(cx * sx), static_cast<float>(cy * sy));
  return m;
}

float panel_width_for(float window_width) { return std::clamp(std::round(0.3f * window_width), 150.f, 360.f); }

namespace {

// The panel's side. When both sides cover the shadow (a probe larger than the room), flip only
// for a clear gain: a shadow sliding to and fro in the middle would otherwise swap sides every
// stroke. Once placed, never while the pointer is near a strip: it is coming for the panel.
PanelSide panel_side(const UiLayoutInput& in, const UiRect& avoid) {
  const PanelSide last = in.last.panel_side;
  const PanelSide other = last == PanelSide::kRight ? PanelSide::kLeft : PanelSide::kRight;
  const bool inside = in.pointer && in.pointer->first >= 0.f && in.pointer->first < in.width &&
                      in.pointer->second >= 0.f && in.pointer->second < in.height;
  if (in.last.panel_placed && inside) {
    const UiRect near_keep = grown(panel_strip(in, last), kPanelPointerKeepPx);
    const UiRect near_flip = grown(panel_strip(in, other), kPanelPointerKeepPx);
    const UiRect at = UiRect::at(in.pointer->first, in.pointer->second, 1.f, 1.f);
    if (intersects(at, near_keep) || intersects(at, near_flip)) return last;
  }
  const std::optional<double>& over = in.last.pointer_on_panel_s;
  if (in.last.panel_placed && over && in.now_s - *over < kPanelPointerMemoryS) return last;
  const float kept = overlap_area(panel_strip(in, last), avoid), flipped = overlap_area(panel_strip(in, other), avoid);
  return kept > 0.f && (flipped == 0.f || flipped < 0.5f * kept) ? other : last;
}

// What a box over r hides: the shadow, and the buttons that weigh like it (text over a button
// hides what the person must press).
float shadow_cost(const UiLayoutInput& in, const UiRect& avoid, const UiRect& r) {
  float c = overlap_area(r, avoid);
  for (const UiRect& b : in.buttons) c += overlap_area(r, grown(b, kShadowMargin));
  return c;
}

// The panel's left edge at in.now_s as placement `p` draws it: on its side's strip, or on the way
// there from p.slide_from_x, eased (smoothstep: no jump in place or speed at either end).
float drawn_panel_x(const UiLayoutInput& in, const UiPlacement& p) {
  const float to = panel_strip(in, p.panel_side).x0;
  if (!p.slide_since_s) return to;
  const double u = std::clamp((in.now_s - *p.slide_since_s) / kPanelSlideS, 0.0, 1.0);
  const float eased = static_cast<float>(u * u * (3.0 - 2.0 * u));
  return p.slide_from_x + (to - p.slide_from_x) * eased;
}

// The panel's side (a flip waits kPanelFlipDwellS, then slides) and the range [x0, x1) its side
// leaves to the boxes.
void place_panel(const UiLayoutInput& in, const UiRect& avoid, UiLayout& out, float& x0, float& x1) {
  const PanelSide want = panel_side(in, avoid);
  out.placement.flip_wanted_since_s.reset();
  if (!in.last.panel_placed || want == in.last.panel_side) {
    out.placement.panel_side = want;  // just opened: placed at once
  } else {
    const double since = in.last.flip_wanted_since_s.value_or(in.now_s);
    const bool flip = in.now_s - since >= kPanelFlipDwellS;
    out.placement.panel_side = flip ? want : in.last.panel_side;
    if (!flip) out.placement.flip_wanted_since_s = since;
  }
  if (!in.last.panel_placed) {
    out.placement.slide_since_s.reset();
  } else if (out.placement.panel_side != in.last.panel_side) {  // sets out from where it is drawn
    out.placement.slide_from_x = drawn_panel_x(in, in.last);
    out.placement.slide_since_s = in.now_s;
  } else if (out.placement.slide_since_s && in.now_s - *out.placement.slide_since_s >= kPanelSlideS) {
    out.placement.slide_since_s.reset();  // arrived
  }
  const UiRect strip = panel_strip(in, out.placement.panel_side);
  out.panel = UiRect::at(drawn_panel_x(in, out.placement), strip.y0, strip.width(), strip.height());
  if (!in.last.panel_placed) out.placement.pointer_on_panel_s.reset();
  if (in.pointer && intersects(UiRect::at(in.pointer->first, in.pointer->second, 1.f, 1.f), *out.panel))
    out.placement.pointer_on_panel_s = in.now_s;
  if (out.placement.panel_side == PanelSide::kRight) x1 = strip.x0;
  else x0 = strip.x1;
}

// The help box, wide or narrow, where it hides the least; the readouts give way to it.
void place_help(const UiLayoutInput& in, const UiRect& avoid, const UiRect& panel, float x0, float x1, UiLayout& out) {
  const auto shadow = [&](const UiRect& r) { return shadow_cost(in, avoid, r); };
  const auto help_cost = [&](const UiRect* hud) {
    return [&, hud](const UiRect& r) {
      return shadow(r) + overlap_area(r, panel) + (hud ? overlap_area(r, *hud) : 0.f);
    };
  };
  const auto place = [&](float w, float h, std::optional<UiRect>& hud) {
    UiRect r = best(help_places(in, x0, x1, w, h), help_cost(&*hud)).rect;
    if (intersects(r, *hud)) {
      // No room for both (text over text reads as neither): the readouts wait until the help,
      // which is transient, hides; the help takes the place that covers the least.
      r = best(help_places(in, x0, x1, w, h), help_cost(nullptr)).rect;
      hud.reset();
    }
    return r;
  };
  std::optional<UiRect> hud_kept = out.hud;
  out.help = place(in.help_w, in.help_h, hud_kept);
  // The wide help covers the shadow or a button wherever it goes: the narrow one, if it covers less.
  if (in.help_narrow_w > 0.f && shadow(*out.help) > 0.f) {
    std::optional<UiRect> hud_narrow = out.hud;
    const UiRect narrow = place(in.help_narrow_w, in.help_narrow_h, hud_narrow);
    if (shadow(narrow) < shadow(*out.help)) {
      out.help = narrow;
      out.help_narrow = true;
      hud_kept = hud_narrow;
    }
  }
  out.hud = hud_kept;
}

}  // namespace

UiLayout layout_ui(const UiLayoutInput& in) {
  UiLayout out;
  const UiRect avoid = in.shadow ? grown(*in.shadow, kShadowMargin) : UiRect{};
  out.placement = in.last;
  out.placement.panel_placed = in.panel;
  float x0 = 0.f, x1 = in.width;  // the range the panel leaves to the boxes
  if (in.panel) place_panel(in, avoid, out, x0, x1);
  // The boxes keep clear of the strip the panel goes to, not of where a slide draws it now: they
  // move once, at the slide's start, instead of following it.
  const UiRect panel = in.panel ? panel_strip(in, out.placement.panel_side) : UiRect{};
  const Candidate hud = best(hud_corners(in, x0, x1, avoid), [&](const UiRect& r) {
    return kShadowWeight * shadow_cost(in, avoid, r) + overlap_area(r, panel);
  });
  out.hud = hud.rect;
  out.placement.hud_corner = hud.corner;
  if (in.help) place_help(in, avoid, panel, x0, x1, out);
  return out;
}

void append_ui_frame(std::string& out, std::uint64_t index, const UiFrameReport& f) {
  out += index ? ",\n    " : "\n    ";
  out += "{\"frame\": " + std::to_string(f.frame);
  append_rect(out, "shadow", f.shadow);
  append_rect(out, "hud", f.hud);
  append_rect(out, "help", f.help);
  append_rect(out, "panel", f.panel);
  out += ", \"buttons\": [";
  for (size_t b = 0; b < f.buttons.size(); ++b) {
    char buf[96];
    const UiRect& r = f.buttons[b];
    std::snprintf(buf, sizeof buf, "%s[%.1f, %.1f, %.1f, %.1f]", b ? ", " : "", r.x0, r.y0, r.x1, r.y1);
    out += buf;
  }
  out += "]}";
}

std::string ui_report_tail(int window_w, int window_h) {
  return "\n  ],\n  \"window\": [" + std::to_string(window_w) + ", " + std::to_string(window_h) + "]\n}\n";
}

std::string ui_report_json(int window_w, int window_h, const std::vector<UiFrameReport>& frames) {
  std::string out = kUiReportHead;
  for (size_t i = 0; i < frames.size(); ++i) append_ui_frame(out, i, frames[i]);
  return out + ui_report_tail(window_w, window_h);
}

}  // namespace ps
