#include "tune/edit_key.h"

#include <cassert>

namespace ps {

namespace {

constexpr std::string_view kMaterials = "materials";
constexpr std::string_view kIntensityLut = "intensity_lut";
constexpr std::string_view kSpeedGainLut = "speed_gain_lut";

}  // namespace

EditKey::EditKey(std::string text)
    : text_(std::move(text)), first_dot_(text_.find('.')), last_dot_(text_.rfind('.')) {}

EditKey EditKey::parse(std::string text) { return EditKey(std::move(text)); }

EditKey EditKey::curve(std::string_view material, CurveKind kind) {
  assert(kind != CurveKind::kNone && "EditKey::curve: a curve kind, not kNone");
  const std::string_view field = kind == CurveKind::kIntensity ? kIntensityLut : kSpeedGainLut;
  return EditKey(std::string(kMaterials) + "." + std::string(material) + "." + std::string(field));
}

std::string_view EditKey::section() const { return std::string_view(text_).substr(0, first_dot_); }

std::string_view EditKey::field() const {
  return last_dot_ == std::string::npos ? std::string_view(text_) : std::string_view(text_).substr(last_dot_ + 1);
}

std::string_view EditKey::material() const {
  if (section() != kMaterials || first_dot_ == last_dot_) return {};
  return std::string_view(text_).substr(first_dot_ + 1, last_dot_ - first_dot_ - 1);
}

CurveKind EditKey::curve() const {
  if (section() != kMaterials || first_dot_ == last_dot_) return CurveKind::kNone;
  if (field() == kIntensityLut) return CurveKind::kIntensity;
  if (field() == kSpeedGainLut) return CurveKind::kSpeedGain;
  return CurveKind::kNone;
}

}  // namespace ps
