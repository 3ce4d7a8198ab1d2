#include "scene/path_policy.h"

#include <algorithm>

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
  return make_error(what + " '" + file.lexically_normal().string() + "', outside the scene's folder (" +
                    fs::path(scene_dir_).lexically_normal().string() +
                    ") and the shipped data: a scene may read only files there. If you trust this scene, "
                    "allow the folder with --allow-path " + resolved.parent_path().string());
}

std::string excerpt(std::string_view text, std::size_t max_chars) {
  std::string out;
  for (char c : text.substr(0, max_chars)) out += (c >= 0x20 && c < 0x7f) ? c : '?';
  if (text.size() > max_chars) out += "...";
  return out;
}

}  // namespace ps
