// The surface pass's shader variants by name (glsl/surface.frag's PS_* defines), as Magnum's
// FlatGL::Flags: a flag set, one helper that turns a valid set into the #define lines, and one
// that says which variant a draw needs. No GL.
//   kShadow         PS_SHADOW=1: the pseudo-shadow (depth lookup, AOV); without it the plain shading
//   kTextured       PS_TEXTURED=1: the Gabor texture (needs kShadow)
//   kStratified     PS_GABOR_STRATIFIED=1: stratified impulses (needs kTextured, no tile)
//   kBakedHermite   PS_GABOR_BAKED=1: a baked tile read with a Hermite lookup (needs kTextured)
//   kBakedLinear    PS_GABOR_BAKED=2: a baked tile of values read bilinearly (needs kTextured)
//   kFilter         PS_GABOR_FILTER=1: the analytic filter (needs kTextured)
//   kFilterSkipped  PS_GABOR_FILTER=2: the filter skipped this frame, its need measured (needs kTextured)
//   kIntensityLut   PS_INTENSITY_LUT=1: the intensity from the material's table (any variant)
#pragma once

#include <cstdint>

#include "gl/shader.h"

namespace ps {

enum class SurfaceFlag : std::uint8_t {
  kShadow = 1u << 0,
  kTextured = 1u << 1,
  kStratified = 1u << 2,
  kBakedHermite = 1u << 3,
  kBakedLinear = 1u << 4,
  kFilter = 1u << 5,
  kFilterSkipped = 1u << 6,
  kIntensityLut = 1u << 7,
};

// A set of SurfaceFlag values; also the key of the pass's program cache.
class SurfaceFlags {
 public:
  constexpr SurfaceFlags() = default;
  constexpr SurfaceFlags(SurfaceFlag f) : bits_(static_cast<std::uint8_t>(f)) {}  // NOLINT: a flag is a set
  constexpr bool has(SurfaceFlag f) const { return (bits_ & static_cast<std::uint8_t>(f)) != 0; }
  constexpr SurfaceFlags& operator|=(SurfaceFlags o) {
    bits_ = static_cast<std::uint8_t>(bits_ | o.bits_);
    return *this;
  }
  constexpr std::uint8_t bits() const { return bits_; }
  constexpr auto operator<=>(const SurfaceFlags&) const = default;

 private:
  std::uint8_t bits_ = 0;
};

constexpr SurfaceFlags operator|(SurfaceFlags a, SurfaceFlags b) { return a |= b; }
constexpr SurfaceFlags operator|(SurfaceFlag a, SurfaceFlag b) { return SurfaceFlags(a) | b; }

// The #define lines of a variant, in the order the sources have always been built with (PS_SHADOW
// and PS_TEXTURED always, the others only when set: a variant without them keeps the source it had
// before they existed, so its shader cache entry and its pixels are unchanged). Asserts (naming this
// function) on a set no draw asks for: texture flags without kTextured, kTextured without kShadow,
// two tile lookups, a tile with stratified impulses, both filter values.
gl::Defines defines_for(SurfaceFlags flags);

// What a draw asks for, before the pass reduces it to a variant (surface_variant).
struct SurfaceVariantRequest {
  bool shadow = true;
  bool textured = true;
  bool stratified = false;
  int baked = 0;         // 0 none, 1 Hermite lookup, 2 bilinear lookup
  int filter = 0;        // 0 none, 1 analytic, 2 analytic skipped this frame
  bool intensity_lut = false;
};

// The variant that draws `r`: the texture's flags only on a textured shadow, stratified impulses
// only without a tile. Always a set defines_for() accepts.
SurfaceFlags surface_variant(const SurfaceVariantRequest& r);

}  // namespace ps
