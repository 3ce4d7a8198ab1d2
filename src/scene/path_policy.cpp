#include "scene/path_policy.h"

#include <algorithm>
#include <optional>

#include "core/install_layout.h"

namespace ps {

namespace fs = std::filesystem;

namespace {

fs::path canonical_or_normal(const fs::path& p) {
  std::error_code ec;
  fs::path c = fs::weakly_canonical(fs::absolute(p, ec), ec);
  return ec ? fs::absolute(p).lexically_normal() : c;
}

bool inside(const fs::path& root, const fs::path& file) {
  auto r = root.begin();
  auto f = file.begin();
  for (; r != root.end(); ++r, ++f) {
    if (r->empty()) continue;  // a trailing separator
    if (f == file.end() || *r != *f) return false;
  }
  return true;
}

// The shipped file `file` most likely meant: the longest tail of its path ("textures/wood.png",
// then "wood.png") that names a file in the shipped data, or directly in one of its folders. A
// scene copied out of scenes/ keeps its "../textures/..." references, which then point nowhere.
std::optional<fs::path> shipped_copy(const fs::path& file) {
  const fs::path data = install::data_dir();
  std::vector<fs::path> parts;
  for (const fs::path& part : file.lexically_normal().relative_path()) parts.push_back(part);
  std::error_code ec;
  for (std::size_t first = 0; first < parts.size(); ++first) {
    fs::path tail;
    for (std::size_t i = first; i < parts.size(); ++i) tail /= parts[i];
    if (fs::is_regular_file(data / tail, ec)) return (data / tail).lexically_normal();
  }
  if (parts.empty()) return std::nullopt;
  for (const fs::directory_entry& e : fs::directory_iterator(data, ec))
    if (fs::is_regular_file(e.path() / parts.back(), ec)) return (e.path() / parts.back()).lexically_normal();
  return std::nullopt;
}

}  // namespace

PathPolicy PathPolicy::for_scene(const std::string& scene_dir, const std::vector<std::string>& allowed) {
  PathPolicy p;
  p.confined_ = true;
  p.scene_dir_ = scene_dir;
  p.roots_.push_back(canonical_or_normal(scene_dir));
  // The shipped data: in the build tree its entries are links to the sources, so each entry's
  // target is a root too.
  const fs::path data = install::data_dir();
  p.roots_.push_back(canonical_or_normal(data));
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(data, ec)) p.roots_.push_back(canonical_or_normal(e.path()));
  // Debian's assimp-testmodels: public package data, where the shipped scenes find Suzanne.
  p.roots_.push_back(canonical_or_normal(kSystemModelDir));
  for (const std::string& dir : allowed) p.roots_.push_back(canonical_or_normal(dir));
  return p;
}

Status PathPolicy::admit(const fs::path& file, const std::string& what) const {
  if (!confined_) return ok_status();
  const fs::path resolved = canonical_or_normal(file);
  if (std::any_of(roots_.begin(), roots_.end(), [&](const fs::path& root) { return inside(root, resolved); }))
    return ok_status();
  // The same words whether `file` exists or not (a scene must not probe which files exist);
  // the shipped data is public, so a shipped file of that name is named.
  std::string message = what + " '" + file.lexically_normal().string() + "', outside the scene's folder (" +
                        fs::path(scene_dir_).lexically_normal().string() +
                        ") and the shipped data: a scene may read only files there.";
  if (const std::optional<fs::path> copy = shipped_copy(file))
    message += " The shipped data has a file of that name, " + copy->string() +
               ": write that path in the scene (no --allow-path needed).";
  return make_error(message + " If you trust this scene, allow the folder with --allow-path " +
                    resolved.parent_path().string());
}

std::string excerpt(std::string_view text, std::size_t max_chars) {
  std::string out;
  for (char c : text.substr(0, max_chars)) out += (c >= 0x20 && c < 0x7f) ? c : '?';
  if (text.size() > max_chars) out += "...";
  return out;
}

}  // namespace ps
