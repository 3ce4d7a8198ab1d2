// Image files in the page: the browser decodes them. The page's file system is preloaded with
// Emscripten's image plugin (web/build_page.sh: --use-preload-plugins), which decodes each PNG
// once at start-up into RGBA bytes; read_image takes those, as src/image/png_io.cpp would take
// the file's (8-bit samples times 1/255, file_bits 8). Every image comes as RGBA: a grey or RGB
// file's channels are repeated and its alpha is 255, which the readers of textures and height
// maps (channel 0, or the first three) read the same.
// What the renderer writes to read back later (button pictures, field maps: src/prepare) is kept
// in memory under its path, quantised as its PNG would be, and read_image finds it there first.
#include <emscripten/emscripten.h>

#include <cstdlib>
#include <map>

#include "image/image.h"

namespace ps {
namespace {

std::map<std::string, Image> g_written;  // the page's thread only

// As src/image/png_io.cpp writes 8 bits (clamped, NaN as 0, rounded) and reads them back.
float as_png_would_store(float v) {
  const float clamped = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
  return static_cast<float>(static_cast<int>(clamped * 255.0f + 0.5f)) * (1.0f / 255.0f);
}

}  // namespace

Result<Image> read_image(const std::string& path) {
  if (const auto it = g_written.find(path); it != g_written.end()) return it->second;
  int width = 0, height = 0;
  char* data = emscripten_get_preloaded_image_data(path.c_str(), &width, &height);
  if (data == nullptr) return make_error(path + ": not an image the page has decoded (is it in the preloaded files?)");
  Image image;
  image.width = width;
  image.height = height;
  image.channels = 4;
  image.file_bits = 8;
  image.pixels.resize(static_cast<size_t>(width) * height * 4);
  constexpr float kScale = 1.0f / 255.0f;  // as png_io.cpp's convert_row
  const auto* bytes = reinterpret_cast<const unsigned char*>(data);
  for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = static_cast<float>(bytes[i]) * kScale;
  std::free(data);
  return image;
}

Status write_image(const std::string& path, const Image& image) {
  Image stored = image;
  for (float& v : stored.pixels) v = as_png_would_store(v);
  stored.file_bits = 8;
  g_written[path] = std::move(stored);
  return ok_status();
}

Status stage_image(OutputSet&, const std::string& path, const Image& image) { return write_image(path, image); }

}  // namespace ps
