#include "tune/file_watch.h"

#include <algorithm>
#include <system_error>

#include "gl/shader.h"

namespace ps {

namespace fs = std::filesystem;

FileWatch::Stamp FileWatch::stamp(const std::string& path) {
  std::error_code ec;
  Stamp s;
  const auto mtime = fs::last_write_time(path, ec);
  if (ec) return s;
  s.exists = true;
  s.mtime = mtime;
  const auto size = fs::file_size(path, ec);
  s.size = ec ? 0 : size;
  return s;
}

void FileWatch::set_files(std::vector<std::string> files) {
  files_ = std::move(files);
  stamps_.clear();
  for (const auto& f : files_) stamps_.push_back(stamp(f));
}

bool FileWatch::changed() {
  std::vector<std::string> now_changed;
  for (std::size_t i = 0; i < files_.size(); ++i) {
    const Stamp now = stamp(files_[i]);
    if (!(now == stamps_[i])) {
      stamps_[i] = now;
      now_changed.push_back(files_[i]);
    }
  }
  if (now_changed.empty()) return false;
  last_changed_ = std::move(now_changed);
  return true;
}

namespace {

bool is_stage(const fs::path& p) {
  const auto ext = p.extension().string();
  return ext == ".vert" || ext == ".frag" || ext == ".comp";
}

void add_glsl_files(const std::string& glsl_root, std::vector<std::string>& out) {
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(glsl_root, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec)) {
    if (!it->is_regular_file(ec)) continue;
    const fs::path p = it->path();
    const auto ext = p.extension().string();
    if (ext != ".glsl" && !is_stage(p)) continue;
    out.push_back(p.lexically_normal().string());
    if (!is_stage(p)) continue;
    // A stage that does not preprocess (broken include) is still watched by its own path.
    auto src = gl::preprocess_shader(p.string(), {}, glsl_root);
    if (!src) continue;
    for (const auto& f : src->files) out.push_back(fs::path(f).lexically_normal().string());
  }
}

}  // namespace

std::vector<std::string> reload_dependencies(const Scene& scene, const std::string& scene_path,
                                             const std::string& glsl_root) {
  std::vector<std::string> out;
  if (!scene_path.empty()) out.push_back(scene_path);
  for (const auto& m : scene.materials)
    if (!m.albedo_texture.empty()) out.push_back(m.albedo_texture);
  for (const auto& s : scene.surfaces) {
    if (!s.heightmap.empty()) out.push_back(s.heightmap);
    if (!s.mesh_file.empty()) out.push_back(s.mesh_file);
  }
  if (!scene.probe.mesh_file.empty()) out.push_back(scene.probe.mesh_file);
  add_glsl_files(glsl_root, out);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace ps
