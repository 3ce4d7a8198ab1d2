// Image files through OpenImageIO: read anything OIIO reads as float; write PNG as 8 bit and
// EXR as 32-bit float, atomically (temp file in the same directory + rename).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include <unistd.h>  // getpid: a per-process temp name so parallel writers never share one

#include <OpenImageIO/imageio.h>

#include "image/image.h"

namespace ps {
namespace {

namespace fs = std::filesystem;

// Larger than any render target we make; anything beyond is a corrupt header or a bug, and
// refusing it avoids allocating tens of GiB before failing.
constexpr int kMaxImageSide = 16384;
constexpr int kMaxChannels = 64;

// OIIO messages can span several lines; the CLI promises one line per error.
std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text.empty() ? std::string("unknown OpenImageIO error") : text;
}

std::string lower_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

Status check_shape(const std::string& path, int width, int height, int channels) {
  if (width <= 0 || height <= 0 || width > kMaxImageSide || height > kMaxImageSide) {
    return make_error(path + ": image size " + std::to_string(width) + "x" + std::to_string(height) +
                      " is outside 1.." + std::to_string(kMaxImageSide));
  }
  if (channels <= 0 || channels > kMaxChannels) {
    return make_error(path + ": image has " + std::to_string(channels) + " channels (expected 1.." +
                      std::to_string(kMaxChannels) + ")");
  }
  return ok_status();
}

// PNG stores 8 bit: clamp to [0,1] and round to nearest (v*255+0.5), so a round trip is within
// 0.5/255. NaN becomes 0, matching what the GL does when it writes NaN to RGBA8.
std::vector<std::uint8_t> quantize_8bit(const std::vector<float>& pixels) {
  std::vector<std::uint8_t> bytes(pixels.size());
  for (size_t i = 0; i < pixels.size(); ++i) {
    float v = std::isnan(pixels[i]) ? 0.0f : std::clamp(pixels[i], 0.0f, 1.0f);
    bytes[i] = static_cast<std::uint8_t>(v * 255.0f + 0.5f);
  }
  return bytes;
}

// Writes the pixels to `file` in the format chosen by `format_path`'s extension (the temp file's
// own name does not end in .png/.exr, so the format is picked from the target path).
Status write_file(const std::string& file, const std::string& format_path, const Image& image) {
  auto out = OIIO::ImageOutput::create(format_path);
  if (!out) {
    return make_error(format_path + ": cannot write image: " + one_line(OIIO::geterror()));
  }
  const std::string ext = lower_extension(format_path);
  const bool is_png = ext == ".png";
  // EXR must be 32-bit float: half would lose precision the reference comparisons rely on.
  OIIO::TypeDesc file_type = is_png ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT;
  OIIO::ImageSpec spec(image.width, image.height, image.channels, file_type);
  // Our pixels are exactly what the GL wrote; without this OIIO assumes premultiplied data and
  // divides colour by alpha when writing PNG (wiping colour where alpha is 0).
  spec.attribute("oiio:UnassociatedAlpha", 1);
  if (!out->open(file, spec)) {
    return make_error(format_path + ": cannot write image: " + one_line(out->geterror()));
  }
  bool written = false;
  if (is_png) {
    std::vector<std::uint8_t> bytes = quantize_8bit(image.pixels);
    written = out->write_image(OIIO::TypeDesc::UINT8, bytes.data());
  } else {
    written = out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data());
  }
  bool closed = out->close();
  if (!written || !closed) {
    return make_error(format_path + ": cannot write image: " + one_line(out->geterror()));
  }
  return ok_status();
}

}  // namespace

Result<Image> read_image(const std::string& path) {
  // Read PNG colour as stored: by default OIIO premultiplies by alpha, so a round trip would
  // not give back what was written.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path, &config);
  if (!in) return make_error(path + ": cannot read image: " + one_line(OIIO::geterror()));
  const OIIO::ImageSpec& spec = in->spec();
  if (Status shape = check_shape(path, spec.width, spec.height, spec.nchannels); !shape) {
    return shape.error();
  }
  if (spec.depth > 1) return make_error(path + ": cannot read image: volume images are not supported");
  Image image;
  image.width = spec.width;
  image.height = spec.height;
  image.channels = spec.nchannels;
  image.pixels.resize(static_cast<size_t>(image.width) * image.height * image.channels);
  // Subimage 0, mip level 0, all channels; OIIO converts any stored type to float ([0,1] for 8 bit).
  if (!in->read_image(0, 0, 0, image.channels, OIIO::TypeDesc::FLOAT, image.pixels.data())) {
    return make_error(path + ": cannot read image: " + one_line(in->geterror()));
  }
  in->close();
  return image;
}

Status write_image(const std::string& path, const Image& image) {
  if (Status shape = check_shape(path, image.width, image.height, image.channels); !shape) return shape;
  if (image.pixels.size() != static_cast<size_t>(image.width) * image.height * image.channels) {
    return make_error(path + ": cannot write image: pixel buffer holds " +
                      std::to_string(image.pixels.size()) + " floats, expected width*height*channels");
  }
  const fs::path target(path);
  std::error_code ec;
  if (target.has_parent_path()) {
    fs::create_directories(target.parent_path(), ec);
    if (ec) return make_error(path + ": cannot create directory: " + ec.message());
  }
  // Same directory as the target, so the rename cannot cross file systems and stays atomic.
  const std::string temp = path + "." + std::to_string(::getpid()) + ".tmp";
  if (Status written = write_file(temp, path, image); !written) {
    fs::remove(temp, ec);
    return written;
  }
  fs::rename(temp, target, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(temp, ignored);
    return make_error(path + ": cannot move temp file into place: " + ec.message());
  }
  return ok_status();
}

}  // namespace ps
