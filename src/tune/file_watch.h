// Polling file watcher for live reload: remembers each file's modification time and size and
// reports when any of them changed (or appeared / disappeared). Polling a few times per second
// on the render thread is portable and cheap (a stat per file), and needs no extra thread.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/result.h"
#include "scene/scene.h"

namespace ps {

class FileWatch {
 public:
  // Replaces the watched set and records the files' current state.
  void set_files(std::vector<std::string> files);
  // True if any watched file changed since set_files() or the previous changed() that
  // returned true; the new state is recorded either way.
  bool changed();
  // The files the last changed() that returned true found changed.
  const std::vector<std::string>& last_changed() const { return last_changed_; }
  const std::vector<std::string>& files() const { return files_; }

 private:
  struct Stamp {
    bool exists = false;
    std::filesystem::file_time_type mtime{};
    std::uintmax_t size = 0;
    bool operator==(const Stamp&) const = default;
  };
  static Stamp stamp(const std::string& path);

  std::vector<std::string> files_;
  std::vector<Stamp> stamps_;
  std::vector<std::string> last_changed_;
};

// Everything a reload depends on: the scene file (if it came from a file), its sibling
// override file, the textures and meshes it references, every file under `glsl_root` and
// the #include dependencies of every shader stage there (preprocess_shader's file list,
// which also catches includes outside the root). Sorted, without duplicates.
std::vector<std::string> reload_dependencies(const Scene& scene, const std::string& scene_path,
                                             const std::string& glsl_root);

}  // namespace ps
