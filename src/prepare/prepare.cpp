#include "prepare/prepare.h"

#include "prepare/button_pictures.h"
#include "prepare/field_map.h"

namespace ps {

Status prepare_scene(Scene& scene, const PrepareOptions& prepare) {
  if (prepare.button_pictures)
    if (Status s = make_button_pictures(scene); !s) return s;
  return make_field_maps(scene);
}

Result<std::unique_ptr<Renderer>> open_renderer(Scene scene, const RendererOptions& options,
                                                const PrepareOptions& prepare) {
  if (Status s = prepare_scene(scene, prepare); !s) return s.error();
  return Renderer::create(scene, options);
}

}  // namespace ps
