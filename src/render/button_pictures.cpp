#include "render/button_pictures.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <unistd.h>

#include "core/hash.h"
#include "image/image.h"
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
  options.button_pictures = false;  // a panel and its worlds may lead to each other
  options.expected_frames = 1;
  auto r = Renderer::create(scene.value(), options);
  if (!r) return r.error();
  if (auto f = r.value()->render(start_frame_input(r.value()->scene())); !f) return f.error();
  return write_image(path, r.value()->read_color());
}

}  // namespace

std::string picture_cache_dir() {
  std::string dir;
  if (const char* d = std::getenv("PSEUDOSHADOW_CACHE_DIR"); d != nullptr && *d != '\0') dir = std::string(d) + "/pictures";
  else if (const char* x = std::getenv("XDG_CACHE_HOME"); x != nullptr && *x != '\0') dir = std::string(x) + "/pseudoshadow/pictures";
  else if (const char* h = std::getenv("HOME"); h != nullptr && *h != '\0') dir = std::string(h) + "/.cache/pseudoshadow/pictures";
  std::error_code ec;
  if (!dir.empty() && (std::filesystem::create_directories(dir, ec), !ec) && access(dir.c_str(), W_OK) == 0) return dir;
  const std::string tmp = (std::filesystem::temp_directory_path(ec) / ("pseudoshadow-" + std::to_string(getuid()))).string() +
                          "/pictures";
  std::filesystem::create_directories(tmp, ec);
  return tmp;
}

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
