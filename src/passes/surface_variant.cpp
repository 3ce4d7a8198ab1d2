#include "passes/surface_variant.h"

#include <cassert>

namespace ps {

namespace {

constexpr SurfaceFlags kTextureFlags = SurfaceFlag::kStratified | SurfaceFlag::kBakedHermite |
                                       SurfaceFlag::kBakedLinear | SurfaceFlag::kFilter | SurfaceFlag::kFilterSkipped;

// Read by the asserts only (compiled out with NDEBUG).
[[maybe_unused]] bool any(SurfaceFlags flags, SurfaceFlags of) { return (flags.bits() & of.bits()) != 0; }

}  // namespace

gl::Defines defines_for(SurfaceFlags flags) {
  using F = SurfaceFlag;
  assert((flags.has(F::kShadow) || !flags.has(F::kTextured)) &&
         "defines_for: kTextured needs kShadow (the texture is part of the pseudo-shadow)");
  assert((flags.has(F::kTextured) || !any(flags, kTextureFlags)) &&
         "defines_for: a Gabor flag (stratified, baked, filter) needs kTextured; build the set with surface_variant()");
  assert(!(flags.has(F::kBakedHermite) && flags.has(F::kBakedLinear)) &&
         "defines_for: kBakedHermite and kBakedLinear are two lookups of one tile; set one");
  assert(!(flags.has(F::kStratified) && any(flags, F::kBakedHermite | F::kBakedLinear)) &&
         "defines_for: kStratified with a baked tile; the tile replaces the impulse sum");
  assert(!(flags.has(F::kFilter) && flags.has(F::kFilterSkipped)) &&
         "defines_for: kFilter and kFilterSkipped are two values of PS_GABOR_FILTER; set one");
  gl::Defines d{{"PS_SHADOW", flags.has(F::kShadow) ? "1" : "0"}, {"PS_TEXTURED", flags.has(F::kTextured) ? "1" : "0"}};
  if (flags.has(F::kStratified)) d.push_back({"PS_GABOR_STRATIFIED", "1"});
  if (flags.has(F::kBakedHermite)) d.push_back({"PS_GABOR_BAKED", "1"});
  if (flags.has(F::kBakedLinear)) d.push_back({"PS_GABOR_BAKED", "2"});
  if (flags.has(F::kFilter)) d.push_back({"PS_GABOR_FILTER", "1"});
  if (flags.has(F::kFilterSkipped)) d.push_back({"PS_GABOR_FILTER", "2"});
  if (flags.has(F::kIntensityLut)) d.push_back({"PS_INTENSITY_LUT", "1"});
  return d;
}

SurfaceFlags surface_variant(const SurfaceVariantRequest& r) {
  using F = SurfaceFlag;
  SurfaceFlags f;
  if (r.shadow) f |= F::kShadow;
  if (r.intensity_lut) f |= F::kIntensityLut;
  if (!r.shadow || !r.textured) return f;
  f |= F::kTextured;
  if (r.baked == 1) f |= F::kBakedHermite;
  if (r.baked == 2) f |= F::kBakedLinear;
  if (r.stratified && r.baked == 0) f |= F::kStratified;
  if (r.filter == 1) f |= F::kFilter;
  if (r.filter == 2) f |= F::kFilterSkipped;
  return f;
}

}  // namespace ps
