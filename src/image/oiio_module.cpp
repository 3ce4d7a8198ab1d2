// libps_image_oiio.so: every image format other than PNG (EXR AOVs, anything else OpenImageIO
// reads), loaded by image_io.cpp with dlopen on first use. It is a separate module because
// linking libOpenImageIO pulls ~270 shared libraries (openvdb, gdal, ffmpeg, ...) and a 25 MB
// static-init heap into every process, which cost `pseudoshadow render` ~60 MiB of peak RSS even
// when it only touches PNG.
#include <algorithm>
#include <exception>
#include <string>

#include <OpenImageIO/imageio.h>

#include "image/image_io_internal.h"

namespace ps::image_io {
namespace {

// OIIO messages can span several lines; the CLI promises one line per error.
std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text.empty() ? std::string("unknown OpenImageIO error") : text;
}

Result<Image> read_file(const std::string& path) {
  // Read colour as stored: by default OIIO premultiplies by alpha, so a round trip would not give
  // back what was written.
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
  // 8-bit only if every channel is stored as uint8 (channelformats lists per-channel types).
  bool all_uint8 = spec.format == OIIO::TypeDesc::UINT8;
  for (const OIIO::TypeDesc& t : spec.channelformats) all_uint8 = all_uint8 && t == OIIO::TypeDesc::UINT8;
  image.file_bits = all_uint8 ? 8 : 0;
  image.pixels.resize(static_cast<size_t>(image.width) * image.height * image.channels);
  // Subimage 0, mip level 0, all channels; OIIO converts any stored type to float ([0,1] for 8 bit).
  if (!in->read_image(0, 0, 0, image.channels, OIIO::TypeDesc::FLOAT, image.pixels.data())) {
    return make_error(path + ": cannot read image: " + one_line(in->geterror()));
  }
  in->close();
  return image;
}

Status write_file(const std::string& file, const std::string& target, const Image& image) {
  auto out = OIIO::ImageOutput::create(target);
  if (!out) return make_error(target + ": cannot write image: " + one_line(OIIO::geterror()));
  // Float files (EXR) must be 32-bit: half would lose precision the reference comparisons rely on.
  // Formats without float storage convert on their own.
  OIIO::ImageSpec spec(image.width, image.height, image.channels, OIIO::TypeDesc::FLOAT);
  // Our pixels are exactly what the GL wrote; without this OIIO assumes premultiplied data.
  spec.attribute("oiio:UnassociatedAlpha", 1);
  if (!out->open(file, spec)) {
    return make_error(target + ": cannot write image: " + one_line(out->geterror()));
  }
  const bool written = out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data());
  const bool closed = out->close();
  if (!written || !closed) {
    return make_error(target + ": cannot write image: " + one_line(out->geterror()));
  }
  return ok_status();
}

// OIIO and its plugins may throw (bad_alloc, Imf exceptions); they become errors here so nothing
// unwinds across the dlopen boundary into the render loop.
Result<Image> read_guarded(const std::string& path) {
  try {
    return read_file(path);
  } catch (const std::exception& e) {
    return make_error(path + ": cannot read image: " + one_line(e.what()));
  }
}

Status write_guarded(const std::string& file, const std::string& target, const Image& image) {
  try {
    return write_file(file, target, image);
  } catch (const std::exception& e) {
    return make_error(target + ": cannot write image: " + one_line(e.what()));
  }
}

}  // namespace
}  // namespace ps::image_io

const ps::image_io::OiioModule* ps_image_oiio_module() {
  static const ps::image_io::OiioModule kModule{ps::image_io::kOiioModuleAbi, ps::image_io::read_guarded,
                                                ps::image_io::write_guarded};
  return &kModule;
}
