// Where the installed data (shaders, scenes, textures) and modules are, found from the binary that
// holds the calling code: the executable, libpseudoshadow.so or the Python module. No path of the
// source or build tree is compiled in, so an installed or unpacked copy works wherever it is put
// and never reads the checkout it was built from (docs/api.md, "Install layout").
//
// Layout: <A>/share/pseudoshadow/{glsl,scenes,textures} and <A>/<libdir>/pseudoshadow/ (modules),
// where <A> is the nearest ancestor of the binary's directory that has share/pseudoshadow/glsl:
// <prefix>/bin/pseudoshadow, <prefix>/lib/<arch>/libpseudoshadow.so and
// <prefix>/lib/python3/dist-packages/pseudoshadow/_core*.so all find <prefix>. The build tree
// has the same layout: build/share/pseudoshadow/* are links to the source tree's glsl/, scenes/
// and textures/ (top-level CMakeLists.txt), so a shader edit needs no rebuild there.
//
// Header-only on purpose: the marker below has internal linkage, so its address lies in whichever
// binary compiled the including file (a shared marker could be bound to another binary's copy).
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace ps::install {

namespace {

const char kBinaryMarker = 0;

// The file of the executable or shared object that holds this code. /proc/self/maps names the
// mapping of any address with an absolute path (dladdr gives argv[0] for the executable, and a
// relative name for a module loaded from a relative sys.path entry). Empty if it cannot be read.
inline std::filesystem::path this_binary() {
  const auto address = reinterpret_cast<std::uintptr_t>(&kBinaryMarker);
  std::ifstream maps("/proc/self/maps");
  std::string line;
  while (std::getline(maps, line)) {
    std::istringstream in(line);
    std::string range, perms, offset, device, inode, path;
    in >> range >> perms >> offset >> device >> inode;
    std::getline(in >> std::ws, path);  // the rest of the line: a path may hold spaces
    const size_t dash = range.find('-');
    if (dash == std::string::npos || path.empty() || path[0] != '/') continue;
    const std::uintptr_t begin = std::stoull(range.substr(0, dash), nullptr, 16);
    const std::uintptr_t end = std::stoull(range.substr(dash + 1), nullptr, 16);
    if (address >= begin && address < end) return path;
  }
  std::error_code ec;
  return std::filesystem::read_symlink("/proc/self/exe", ec);
}

// How many directories above the binary's own are searched: the Python module sits four below
// the prefix (lib/python3/dist-packages/pseudoshadow).
inline constexpr int kMaxLevelsUp = 4;

// <A>/share/pseudoshadow for the nearest ancestor <A> of the binary's directory that has
// share/pseudoshadow/glsl; if none has, <binary dir>/../share/pseudoshadow (where an install
// puts it), so that a message about a missing file names the place it was expected.
inline std::filesystem::path data_dir() {
  const std::filesystem::path binary_dir = this_binary().parent_path();
  std::filesystem::path dir = binary_dir;
  std::error_code ec;
  for (int level = 0; level <= kMaxLevelsUp && !dir.empty(); ++level) {
    const std::filesystem::path candidate = dir / "share" / "pseudoshadow";
    if (std::filesystem::is_directory(candidate / "glsl", ec)) return candidate;
    if (dir == dir.root_path()) break;
    dir = dir.parent_path();
  }
  return (binary_dir / ".." / "share" / "pseudoshadow").lexically_normal();
}

}  // namespace

}  // namespace ps::install
