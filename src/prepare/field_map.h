// The field-magnitude map of Sandia's Field world ("show what people would rather look at
// than feel"): a surface with `field_map = true` (a plane or a box, lying along world X and Y)
// shows |F|, the force the scene's charges put on the probe, as a colour map over its top. |F| is
// evaluated in the horizontal plane at the charges' mean height (where their pulls can cancel),
// or where the probe's centre is when it rests on that top if that is higher, on
// a kFieldMapSize square grid covering the surface, log-scaled between the 2nd and 98th
// percentiles and coloured dark blue (weak: the weak spots) through magenta to yellow (strong).
// The map is the surface's albedo texture (a PNG in the picture cache, prepare/picture_cache.h,
// named by a hash of everything it depends on). Live charges added in `run` are not in it.
#pragma once

#include "core/result.h"
#include "image/image.h"
#include "scene/scene.h"

namespace ps {

inline constexpr int kFieldMapSize = 256;

// The map of surface `s` (RGB, top row = largest y), in [0, 1].
Image field_map_image(const Scene& scene, const Surface& s);
// Every field-map surface's image made (or found in the cache) and set as its material's
// albedo texture. No GL needed.
Status make_field_maps(Scene& scene);

}  // namespace ps
