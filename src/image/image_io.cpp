// Image files: PNG through libpng (png_io.cpp); every other format through OpenImageIO in the
// module libps_image_oiio.so, loaded with dlopen on first use (oiio_module.cpp says why). Reads
// choose by file signature, writes by extension. Writes are atomic (core/output_set.h: a temp
// file in the same directory, fsync, rename).
#include <cctype>
#include <filesystem>
#include <mutex>
#include <string>
#include <system_error>
#include <vector>

#include <dlfcn.h>

#include "core/install_layout.h"
#include "image/image.h"
#include "image/image_io_internal.h"

// Both come from CMake (src/image/CMakeLists.txt): the module's file name, looked for next to
// the running executable, and where the build put it, for binaries that live elsewhere (tests).
#ifndef PS_OIIO_MODULE_NAME
#error "PS_OIIO_MODULE_NAME must be defined by the build (src/image/CMakeLists.txt)"
#endif
#ifndef PS_INSTALL_LIBDIR
#error "PS_INSTALL_LIBDIR must be defined by the build (src/image/CMakeLists.txt)"
#endif
#ifndef PS_OIIO_MODULE_PATH
#error "PS_OIIO_MODULE_PATH must be defined by the build (src/image/CMakeLists.txt)"
#endif

namespace ps {
namespace {

namespace fs = std::filesystem;
using image_io::OiioModule;

std::string lower_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

struct LoadedModule {
  const OiioModule* table = nullptr;
  std::string failure;  // every path tried with its dlerror(), when table is null
};

// dlopens `path` and checks its entry point; on failure appends why to `failure`.
const OiioModule* try_load(const std::string& path, std::string& failure) {
  if (!failure.empty()) failure += "; ";
  // RTLD_LOCAL keeps OIIO's symbols out of the global namespace. The handle is never closed:
  // OIIO starts a thread pool and registers exit handlers that must outlive any unload.
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = dlerror();
    failure += why ? why : path + ": dlopen failed";
    return nullptr;
  }
  using Entry = const OiioModule* (*)();
  auto entry = reinterpret_cast<Entry>(dlsym(handle, PS_OIIO_MODULE_ENTRY));
  if (!entry) {
    failure += path + ": no " PS_OIIO_MODULE_ENTRY " entry point (not our module?)";
    return nullptr;
  }
  const OiioModule* table = entry();
  if (!table || table->abi != image_io::kOiioModuleAbi) {
    failure += path + ": built by another version of pseudoshadow (rebuild it)";
    return nullptr;
  }
  return table;
}

// Loaded once per process, on first use, from whichever thread gets there first.
const LoadedModule& oiio_module() {
  static LoadedModule loaded;
  static std::once_flag once;
  std::call_once(once, [] {
    std::vector<std::string> candidates;
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) candidates.push_back((exe.parent_path() / PS_OIIO_MODULE_NAME).string());
    // Installed: <prefix>/<libdir>/pseudoshadow/, found from the binary holding this code (the
    // Python module and libpseudoshadow.so are not beside any executable; core/install_layout.h).
    candidates.push_back((install::data_dir() / ".." / ".." / PS_INSTALL_LIBDIR / "pseudoshadow" /
                          PS_OIIO_MODULE_NAME).lexically_normal().string());
    if (candidates.empty() || candidates.front() != PS_OIIO_MODULE_PATH) {
      candidates.push_back(PS_OIIO_MODULE_PATH);
    }
    for (const std::string& path : candidates) {
      loaded.table = try_load(path, loaded.failure);
      if (loaded.table) return;
    }
  });
  return loaded;
}

}  // namespace

Result<const OiioModule*> image_io::load_oiio_module(const std::string& what) {
  const LoadedModule& module = oiio_module();
  if (module.table) return module.table;
  return make_error(what + ": this format needs the OpenImageIO module (" PS_OIIO_MODULE_NAME "): " +
                    module.failure + "; PNG works without it");
}

Result<Image> read_image(const std::string& path) {
  Result<bool> is_png = image_io::has_png_signature(path);
  if (!is_png) return is_png.error();
  if (*is_png) return image_io::read_png(path);
  Result<const OiioModule*> module = image_io::load_oiio_module(path + ": cannot read image");
  if (!module) return module.error();
  return (*module)->read(path);
}

namespace {

// Encodes `image` into `file` (a temp file) in the format `path`'s extension names.
Status encode_image(const std::string& file, const std::string& path, const Image& image) {
  if (Status shape = image_io::check_shape(path, image.width, image.height, image.channels); !shape) {
    return shape;
  }
  if (image.pixels.size() != static_cast<size_t>(image.width) * image.height * image.channels) {
    return make_error(path + ": cannot write image: pixel buffer holds " +
                      std::to_string(image.pixels.size()) + " floats, expected width*height*channels");
  }
  if (lower_extension(path) == ".png") return image_io::write_png(file, path, image);
  Result<const OiioModule*> module = image_io::load_oiio_module(path + ": cannot write image");
  if (!module) return module.error();
  return (*module)->write(file, path, image);
}

}  // namespace

Status stage_image(OutputSet& outputs, const std::string& path, const Image& image) {
  return outputs.stage(path, [&](const std::string& file) { return encode_image(file, path, image); });
}

Status write_image(const std::string& path, const Image& image) {
  OutputSet outputs;
  if (Status s = stage_image(outputs, path, image); !s) return s;
  return outputs.publish();
}

}  // namespace ps
