// Internal to src/image: pieces shared by the dispatcher (image_io.cpp), the libpng codec
// (png_io.cpp) and the OpenImageIO module (oiio_module.cpp). Header-only where the module needs
// it, because the module links neither ps_image nor ps_core (it is loaded into a process that
// already holds them).
#pragma once

#include <string>

#include "core/result.h"
#include "image/image.h"

namespace ps::image_io {

// Larger than any render target we make; anything beyond is a corrupt header or a bug, and
// refusing it avoids allocating tens of GiB before failing.
constexpr int kMaxImageSide = 16384;
constexpr int kMaxChannels = 64;

inline Status check_shape(const std::string& path, int width, int height, int channels) {
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

// True when the file starts with the 8-byte PNG signature. A missing or unreadable file is an
// error naming the path; a file shorter than the signature is simply "not PNG".
Result<bool> has_png_signature(const std::string& path);

// libpng codec (png_io.cpp). read_png: any PNG, as float. write_png writes `image` to `file`
// (the temp name); errors name `target` (the path the caller asked for).
Result<Image> read_png(const std::string& path);
Status write_png(const std::string& file, const std::string& target, const Image& image);

// The OpenImageIO module's entry point (libps_image_oiio.so, loaded with dlopen on the first
// non-PNG file). C++ types cross the boundary: the module is built by the same CMake project with
// the same compiler and standard library, and `abi` catches a stale module from another build.
constexpr int kOiioModuleAbi = 1;
struct OiioModule {
  int abi = 0;
  Result<Image> (*read)(const std::string& path) = nullptr;
  // Format chosen by `target`'s extension (the temp name `file` ends in .tmp).
  Status (*write)(const std::string& file, const std::string& target, const Image& image) = nullptr;
};

// The loaded module, dlopened on the first call (thread-safe) and kept for the process lifetime.
// `what` starts the error ("<path>: cannot read image"), which names every path tried and
// dlerror(). read_image/write_image use it; tests call it to read a PNG through OIIO as well.
Result<const OiioModule*> load_oiio_module(const std::string& what);

}  // namespace ps::image_io

#define PS_OIIO_MODULE_ENTRY "ps_image_oiio_module"
// Exported by name even though the module builds with hidden visibility.
extern "C" __attribute__((visibility("default"))) const ps::image_io::OiioModule* ps_image_oiio_module();
