#include "prepare/button_pictures.h"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/hash.h"
#include "image/image.h"
#include "prepare/picture_cache.h"
#include "prepare/prepare.h"
#include "render/renderer.h"
#include "scene/scene_io.h"

namespace ps {

namespace {

Result<std::string> picture_path(const std::string& scene_file) {
  std::ifstream in(scene_file, std::ios::binary);
  if (!in) return make_error(scene_file + ": cannot read");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  char name[64];
  // kPictureVersion: a picture is a render, so a change that changes renders (one whose commit
  // regenerates the golden images) bumps it, and no cache keeps a picture of the old renderer.
  std::snprintf(name, sizeof name, "/%016llx_%d.png",
                static_cast<unsigned long long>(fnv1a(bytes + "|picture v" + std::to_string(kPictureVersion) + "|" +
                                                      std::to_string(kPictureSize))),
                kPictureSize);
  return picture_cache_dir() + name;
}

bool usable(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return false;
  auto img = read_image(path);
  return img && img->width == kPictureSize && img->height == kPictureSize;
}

Status render_picture(const std::string& scene_file, const std::string& path) {
  auto scene = load_scene(scene_file);
  if (!scene) return scene.error();
  scene->render.width = scene->render.height = kPictureSize;
  RendererOptions options;
  options.expected_frames = 1;
  // No pictures of its own: a panel and its worlds may lead to each other.
  auto r = open_renderer(scene.value(), options, {.button_pictures = false});
  if (!r) return r.error();
  if (Status f = r.value()->render_frame(); !f) return f;  // the scene's start view, as `render` draws it
  return write_image(path, r.value()->read_color());
}

}  // namespace

Status make_button_pictures(Scene& scene) {
  for (const Button& b : scene.buttons) {
    if (!b.picture || b.picture_material < 0) continue;
    const std::string where = scene.path + ":" + std::to_string(b.line) + ": picture of " + b.action_target + ": ";
    auto path = picture_path(b.action_target);
    if (!path) return make_error(where + path.error().message);
    if (!usable(path.value()))
      if (Status s = render_picture(b.action_target, path.value()); !s) return make_error(where + s.error().message);
    Material& m = scene.materials[static_cast<std::size_t>(b.picture_material)];
    m.albedo_texture = path.value();
    m.albedo_texture_scale_mm = b.size_mm.x;  // square pictures, as wide as the button
    m.albedo_texture_offset_mm = glm::dvec2(b.center.x, b.center.y) - 0.5 * b.size_mm;
  }
  return ok_status();
}

}  // namespace ps
