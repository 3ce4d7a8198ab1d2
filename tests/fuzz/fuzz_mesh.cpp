// libFuzzer target: mesh import through assimp and our wrapper. The first byte picks the file
// extension (assimp chooses its importer by it), the rest is the file. Whatever assimp returns
// - nothing, empty or degenerate meshes, NaN vertices - must become a Mesh with finite bounds or
// an Error, never a crash.
#include <unistd.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "scene/mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The supported formats plus three that load_mesh_file must refuse without reading them.
  static const char* const kExt[] = {"obj", "ply", "stl", "off", "gltf", "dae", "3ds", "x"};
  if (size < 1) return 0;
  const std::string ext = kExt[data[0] % (sizeof(kExt) / sizeof(kExt[0]))];
  const auto path = std::filesystem::temp_directory_path() /
                    ("ps_fuzz_mesh_" + std::to_string(static_cast<long>(getpid())) + "." + ext);
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  auto mesh = ps::load_mesh_file(path.string());
  if (!mesh.ok()) {
    if (mesh.error().message.empty()) __builtin_trap();
    return 0;
  }
  ps::transform_mesh(mesh.value(), 2.0, {10.0, 20.0, 30.0}, {1.0, 2.0, 3.0});
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(mesh->bounds_min[i]) || !std::isfinite(mesh->bounds_max[i])) __builtin_trap();
  return 0;
}
