// The AOVs Renderer::read_aov() returns (image size, top row first, float), by value and by
// the name the CLI's --aov takes; one table (aov.cpp) says where each comes from.
#pragma once

#include <string>
#include <vector>

#include "core/result.h"

namespace ps {

enum class Aov {
  kIntensity,     // 1 channel: pseudo-shadow intensity [0, 1], 0 where there is none
  kDistance,      // 1 channel: signed probe-surface distance d along the reference normal, mm;
                  //   kNoProbeDistance (NaN, passes/surface.h) where no probe is above the
                  //   pixel: test it with std::isnan
  kTexture,       // 1 channel: Gabor texture value in sigmas, 0 where it is not evaluated
  kNormal,        // 3 channels: visible front-facing normal, 0 where no surface is drawn
  kDisplacement,  // 4 channels: per pixel (w * disp xyz mm, w), the weighted displacement's terms
};

// Where an AOV's pixels come from.
enum class AovSource {
  kSurfaceAov,    // one channel of the surface pass's aov() target
  kNormal,        // the surface pass's normal() target, xyz
  kDisplacement,  // drawn on request by ReductionsPass::displacement_aov()
};
struct AovInfo {
  Aov aov;
  const char* name;
  AovSource source;
  int channel;  // kSurfaceAov: the channel of aov() (intensity, d, texture, resistance)
};
const AovInfo& aov_info(Aov aov);

// The names, in enum order: intensity, distance, texture, normal, displacement.
const std::vector<std::string>& aov_names();
// An unknown name is the error "unknown AOV 'NAME' (known: intensity, distance, ...)".
Result<Aov> parse_aov(const std::string& name);

}  // namespace ps
