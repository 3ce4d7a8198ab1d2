// Which files a scene may make the program read (docs/scene-format.md, "Files a scene may read").
// People share scenes, and a server may render submitted ones: a scene's file references
// (include, albedo_texture, heightmap, mesh_file, the lookup tables, a button's "scene:FILE")
// must lie in the scene's own folder tree, in the shipped data (share/pseudoshadow/ and
// kSystemModelDir), or in a folder the user allowed (`--allow-path DIR`, the APIs'
// `allow_paths`). Paths are compared after resolving links, so neither `..` nor a link inside the
// tree escapes it. A value the user wrote (`--set`, an `--overrides` file) is the user's own and
// is not confined.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/result.h"

namespace ps {

// Public model files from a Debian package (assimp-testmodels), counted as shipped data: the
// shipped scenes take Suzanne from there.
inline constexpr const char* kSystemModelDir = "/usr/share/assimp/models";

class PathPolicy {
 public:
  // Unconfined: admits every path (for callers that read files the user named themselves).
  PathPolicy() = default;

  // The tree of `scene_dir`, the shipped data and each directory of `allowed` (relative ones
  // against the working directory).
  static PathPolicy for_scene(const std::string& scene_dir, const std::vector<std::string>& allowed = {});

  // Ok when `file` lies inside one of the roots; otherwise one line naming the file, where a
  // scene may read from, and the --allow-path that would admit it. `what` names the reference
  // and comes first ("names": "'albedo_texture' names '/x.png', outside the scene's folder ...").
  Status admit(const std::filesystem::path& file, const std::string& what) const;

 private:
  bool confined_ = false;
  std::string scene_dir_;
  std::vector<std::filesystem::path> roots_;  // canonical
};

// At most `max_chars` of `text` for an error message, every byte outside printable ASCII shown
// as '?', with "..." when cut: a file that is not of the expected kind is quoted, not echoed.
std::string excerpt(std::string_view text, std::size_t max_chars = 24);

}  // namespace ps
