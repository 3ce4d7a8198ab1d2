// Scene preparation: what a scene needs made before a renderer can draw it (button pictures,
// field maps: textures the scene file names only by what they show). It runs before
// Renderer::create, which draws a prepared scene as given; making a picture opens a renderer of
// its own here, never inside another renderer's creation.
#pragma once

#include <memory>

#include "core/result.h"
#include "render/renderer.h"
#include "scene/scene.h"

namespace ps {

struct PrepareOptions {
  // Picture buttons get their pictures (prepare/button_pictures.h); false for the pictures' own
  // renders (a panel and its worlds may lead to each other) and tests that need no GL beyond it.
  bool button_pictures = true;
};

// The button pictures (needs a current GL context) and field maps of `scene`, made or found in
// the picture cache and set as their materials' albedo textures.
Status prepare_scene(Scene& scene, const PrepareOptions& prepare = {});

// prepare_scene, then Renderer::create: what every command that draws a scene file opens.
Result<std::unique_ptr<Renderer>> open_renderer(Scene scene, const RendererOptions& options,
                                                const PrepareOptions& prepare = {});

}  // namespace ps
