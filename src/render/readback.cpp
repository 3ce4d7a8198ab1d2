#include "render/readback.h"

#include <cstdint>
#include <vector>

namespace ps {

Image read_region(const gl::Texture& tex, int w, int h, int channels_out, GLenum format, GLenum type) {
  const int in_channels = 4;
  Image img;
  img.width = w;
  img.height = h;
  img.channels = channels_out;
  img.pixels.resize(static_cast<size_t>(w) * h * channels_out);
  const size_t n = static_cast<size_t>(w) * h * in_channels;
  // Converted straight from the readback buffer: no float copy of a byte image (at 2048^2 that
  // copy alone was 64 MiB of the render's peak memory).
  auto flip_into = [&](const auto* src, float divisor) {
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int c = 0; c < channels_out; ++c)
          img.at(x, y, c) = static_cast<float>(src[(static_cast<size_t>(h - 1 - y) * w + x) * in_channels + c]) / divisor;
  };
  if (type == GL_UNSIGNED_BYTE) {
    std::vector<std::uint8_t> b(n);
    glGetTextureSubImage(tex.id(), 0, 0, 0, 0, w, h, 1, format, type, static_cast<GLsizei>(b.size()), b.data());
    flip_into(b.data(), 255.0f);
  } else {
    std::vector<float> f(n);
    glGetTextureSubImage(tex.id(), 0, 0, 0, 0, w, h, 1, format, type,
                         static_cast<GLsizei>(f.size() * sizeof(float)), f.data());
    flip_into(f.data(), 1.0f);
  }
  return img;
}

Image read_color_image(const SurfacePass& surface) {
  return read_region(surface.color(), surface.width(), surface.height(), 3, GL_RGBA, GL_UNSIGNED_BYTE);
}

// The surface pass writes its AOV target inside the footprint's rectangle only (the texture
// keeps older frames' values elsewhere): outside it every pixel is (0, NaN, 0, 0), the values
// that say "no probe above this pixel" (passes/surface.h).
void read_surface_aov_into(const SurfacePass& surface, int channel, Image& out, std::vector<float>& raw) {
  static constexpr float kNone[4] = {0.0f, kNoProbeDistance, 0.0f, 0.0f};
  const int w = surface.width(), h = surface.height();
  raw.resize(static_cast<size_t>(w) * h * 4);
  glGetTextureSubImage(surface.aov().id(), 0, 0, 0, 0, w, h, 1, GL_RGBA, GL_FLOAT,
                       static_cast<GLsizei>(raw.size() * sizeof(float)), raw.data());
  out.width = w;
  out.height = h;
  out.channels = 1;
  out.file_bits = 0;
  out.pixels.resize(static_cast<size_t>(w) * h);
  const PixelRect& rect = surface.shadow_rect();  // GL window coordinates: row 0 is the bottom
  for (int y = 0; y < h; ++y)  // out: top row first
    for (int x = 0; x < w; ++x)
      out.at(x, y, 0) = rect.contains(x, h - 1 - y) ? raw[(static_cast<size_t>(h - 1 - y) * w + x) * 4 + channel]
                                                    : kNone[channel];
}

Result<Image> read_aov_image(const SurfacePass& surface, const ReductionsPass& reductions, Aov aov) {
  const AovInfo& e = aov_info(aov);
  const int w = surface.width(), h = surface.height();
  switch (e.source) {
    case AovSource::kSurfaceAov: {
      Image img;
      std::vector<float> raw;
      read_surface_aov_into(surface, e.channel, img, raw);
      return img;
    }
    case AovSource::kNormal:
      return read_region(surface.normal(), w, h, 3, GL_RGBA, GL_FLOAT);
    case AovSource::kDisplacement: {
      auto tex = reductions.displacement_aov(surface);
      if (!tex) return tex.error();
      return read_region(tex.value(), w, h, 4, GL_RGBA, GL_FLOAT);
    }
  }
  return make_error("read_aov: unhandled AOV source");  // unreachable: the switch covers AovSource
}

Status read_aov_image_into(const SurfacePass& surface, const ReductionsPass& reductions, Aov aov, Image& out,
                          std::vector<float>& raw) {
  const AovInfo& e = aov_info(aov);
  if (e.source == AovSource::kSurfaceAov) {
    read_surface_aov_into(surface, e.channel, out, raw);
    return ok_status();
  }
  auto img = read_aov_image(surface, reductions, aov);  // the other sources are read on request only
  if (!img) return img.error();
  out = std::move(img.value());
  return ok_status();
}

}  // namespace ps
