// A scene key as an edit names it: `--set KEY=VALUE`, a line of an override file, the tuning
// panel ("camera.position", "materials.wood.lambda_max", "materials.wood.intensity_lut"). Parsed
// once into the parts the tuning acts on, so no caller matches prefixes of the text; the text is
// what --set and the override files carry, unchanged (tune/overrides_file.h).
//
// There is no "changes the haptic scene" predicate on purpose: every edit restarts the view's
// pose (TuneSession's reload policy), and `run` restarts the haptic loop's view with it by
// rebuilding the haptic scene after any edit (TuneSession::edits_generation), so skipping the
// rebuild for a look-only key would leave the two views apart.
#pragma once

#include <string>
#include <string_view>

namespace ps {

// A material's curve edited as a table (TuneSession::set_curve): intensity over distance, or the
// speed gain over speed.
enum class CurveKind { kNone, kIntensity, kSpeedGain };

class EditKey {
 public:
  // Any text: a key without dots is all section and field.
  static EditKey parse(std::string text);
  // "materials.NAME.intensity_lut" or "materials.NAME.speed_gain_lut" (`kind` not kNone).
  static EditKey curve(std::string_view material, CurveKind kind);

  const std::string& text() const { return text_; }
  std::string_view section() const;   // the first component: "camera", "materials", "probe", ...
  std::string_view field() const;     // the last component: "position", "lambda_max", ...
  std::string_view material() const;  // "materials.NAME.FIELD": NAME (dots and all); else empty
  bool camera() const { return section() == "camera"; }
  // A material's *_lut key: which curve; kNone for every other key.
  CurveKind curve() const;

 private:
  explicit EditKey(std::string text);
  std::string text_;
  std::size_t first_dot_, last_dot_;  // std::string::npos: none
};

}  // namespace ps
