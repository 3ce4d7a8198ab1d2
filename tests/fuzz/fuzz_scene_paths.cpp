// libFuzzer target: the rule of which files a scene may read (scene/path_policy.h). A sandbox is
// made once: tree/ (the scene's folder, with a sub-folder, a table and a link that points out of
// the tree) beside out/ (a table, a secret and a folder). Each input line is a path; the scene
// names it as an intensity_lut, an include and a button's scene in turn. The properties, checked
// without the policy's own code: a scene that loads read its table from inside tree/ (or the
// shipped data), and no message ever quotes the secret's marker.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "scene/scene_io.h"

namespace fs = std::filesystem;

namespace {

constexpr const char* kMarker = "FUZZ-SECRET-MARKER";

struct Sandbox {
  fs::path root;
  ~Sandbox() {
    std::error_code ec;
    fs::remove_all(root, ec);
  }
};

const fs::path& sandbox() {
  static const Sandbox box{[] {
    const fs::path r = fs::temp_directory_path() / ("ps_fuzz_paths_" + std::to_string(::getpid()));
    fs::remove_all(r);
    fs::create_directories(r / "tree" / "sub");
    fs::create_directories(r / "out" / "dir");
    const char* lut = "lut distance_mm intensity\n0 1\n2 0\n";
    std::ofstream(r / "tree" / "in.lut") << lut;
    std::ofstream(r / "tree" / "sub" / "in.lut") << lut;
    std::ofstream(r / "out" / "out.lut") << lut;
    std::ofstream(r / "out" / "secret") << "lut " << kMarker << "\n";
    std::ofstream(r / "out" / "lib.toml") << "[materials.x]\n# " << kMarker << "\n";
    std::error_code ec;
    fs::create_symlink(r / "out", r / "tree" / "link", ec);
    return r;
  }()};
  return box.root;
}

// Inside `dir` after resolving links: an independent prefix test on canonical strings.
bool under(const fs::path& file, const fs::path& dir) {
  std::error_code ec;
  const std::string f = fs::weakly_canonical(file, ec).string();
  const std::string d = fs::weakly_canonical(dir, ec).string() + "/";
  return f.rfind(d, 0) == 0;
}

std::string toml_string(const std::string& path) {
  std::string out = "\"";
  for (char c : path) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

void check(const std::string& text) {
  const fs::path tree = sandbox() / "tree";
  auto scene = ps::parse_scene(text, "fuzz.toml", tree.string());
  if (!scene.ok()) {
    // The marker may be quoted only when the scene itself wrote it (a path naming it).
    const bool quoted_secret = scene.error().message.find(kMarker) != std::string::npos &&
                               text.find(kMarker) == std::string::npos;
    if (scene.error().message.empty() || quoted_secret) __builtin_trap();
    return;
  }
  for (const ps::Material& m : scene->materials)
    if (!m.intensity_lut.file.empty() && under(m.intensity_lut.file, sandbox() / "out")) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  for (std::string path; std::getline(lines, path);) {
    if (path.size() > 512) continue;
    const std::string surf = "\n[[surfaces]]\nmaterial = \"wood\"\n";
    check("[materials.wood]\nintensity_lut = " + toml_string(path) + surf);
    check("include = [" + toml_string(path) + "]\n[materials.wood]" + surf);
    check("[materials.wood]" + surf + "[[buttons]]\naction = " + toml_string("scene:" + path) + "\n");
  }
  return 0;
}
