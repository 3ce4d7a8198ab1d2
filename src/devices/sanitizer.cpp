#include "devices/sanitizer.h"

#include <cmath>

namespace ps {

std::optional<DeviceSample> DeviceSanitizer::filter(const DeviceSample& in) {
  if (!in.valid) { ++counts_.invalid; return std::nullopt; }
  const glm::dvec3& p = in.position_mm;
  if (!std::isfinite(in.time_s) || !std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
    ++counts_.non_finite;
    return std::nullopt;
  }
  if (last_ && in.time_s < last_->time_s) { ++counts_.time_backwards; return std::nullopt; }
  DeviceSample out = in;
  if (last_) {
    const glm::dvec3 d = p - last_->position_mm;
    const double len = glm::length(d);
    if (len > params_.max_jump_mm) {
      out.position_mm = last_->position_mm + d * (params_.max_jump_mm / len);
      ++counts_.jumps_clamped;
    }
  }
  last_ = out;
  return out;
}

}  // namespace ps
