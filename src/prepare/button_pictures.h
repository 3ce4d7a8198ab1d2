// Pictures on buttons (issue "The Virtual Universe", A Virtual Universe §2: "a virtual wall with
// four buttons each containing a picture of the world to which it leads"). A [[buttons]] entry with
// `picture = true` and a "scene:FILE" action gets a picture of FILE, rendered headless by the
// renderer (kPictureSize square, one frame, the scene's own camera, no pictures of its own: a
// panel and its worlds may lead to each other), as its plate's albedo texture, mapped along
// world X/Y onto the plate (a panel facing +Z). Made before the scene's renderer is created
// (prepare/prepare.h), so the renderer never creates renderers.
// The pictures are cached as PNG files in the picture cache (prepare/picture_cache.h), named by
// a hash of the scene file's bytes, kPictureVersion and the picture's size: a picture is made
// again when that file or the renderer changes, and only then. Written atomically (several
// processes may share the cache; the last writer's identical picture wins); a cached file that
// does not read back as a kPictureSize PNG is never trusted, but made again.
#pragma once

#include <string>

#include "core/result.h"
#include "scene/scene.h"

namespace ps {

inline constexpr int kPictureSize = 128;
// The renderer's version in the pictures' cache names: bumped by every change that changes
// renders (its commit regenerates the golden images), so a cache never hands back a picture of
// an older renderer. 2: the Gabor noise's new cell seeds and the true distance by default.
inline constexpr int kPictureVersion = 2;

// For every picture button of `scene`: its picture's file (cached or rendered now, which needs
// a current GL context) set as the albedo texture of the button's picture material. A target
// scene that cannot be loaded or rendered is an error naming the button's line.
Status make_button_pictures(Scene& scene);

}  // namespace ps
