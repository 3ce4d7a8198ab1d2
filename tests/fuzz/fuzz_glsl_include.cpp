// libFuzzer target: the GLSL #include resolver and the log mapper. The input becomes the root
// shader of a small tree whose lib/ holds a file that includes itself (a cycle) and one that
// includes a missing file; the input is also fed to map_shader_log as a driver log.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "gl/shader.h"

namespace {

std::filesystem::path make_tree() {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("ps_fuzz_glsl_" + std::to_string(static_cast<long>(getpid())));
  std::filesystem::create_directories(dir / "lib");
  std::ofstream(dir / "lib" / "a.glsl") << "#pragma once\nfloat a() { return 1.0; }\n";
  std::ofstream(dir / "lib" / "cycle.glsl") << "#include \"cycle.glsl\"\n";
  std::ofstream(dir / "lib" / "missing.glsl") << "#include \"nowhere.glsl\"\n";
  return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path dir = make_tree();
  const std::string text(reinterpret_cast<const char*>(data), size);
  const auto root = dir / "root.frag";
  std::ofstream(root, std::ios::binary | std::ios::trunc) << text;
  auto src = ps::gl::preprocess_shader(root.string(), {{"PS_X", "1"}}, dir.string());
  if (!src.ok() && src.error().message.empty()) __builtin_trap();
  if (src.ok()) (void)ps::gl::map_shader_log(text, src->files);
  (void)ps::gl::map_shader_log(text, {"a.frag", "lib/b.glsl"});
  return 0;
}
