#include "prepare/prepare.h"
#include "tune/tune_session.h"

#include <filesystem>

#include "core/file_io.h"
#include "gl/shader.h"
#include "scene/scene_io.h"
#include "tune/edit_key.h"
#include "tune/overrides_file.h"

namespace ps {

Result<std::unique_ptr<TuneSession>> TuneSession::open(TuneSource source) {
  auto scene = load_scene_or_default(source.scene_path, source.overrides, source.allow_paths);
  if (!scene) return scene.error();
  return open(std::move(source), std::move(scene.value()));
}

Result<std::unique_ptr<TuneSession>> TuneSession::open(TuneSource source, Scene scene) {
  if (source.renderer.glsl_root.empty()) source.renderer.glsl_root = gl::default_glsl_root();
  std::unique_ptr<TuneSession> s(new TuneSession());
  s->source_ = std::move(source);
  if (Status st = s->rebuild({}, {}, false, std::move(scene)); !st) return st.error();
  return s;
}

Result<Scene> TuneSession::load(const std::map<std::string, std::string>& edits) const {
  std::vector<std::string> sets = source_.overrides;
  for (const auto& [key, value] : edits) sets.push_back(key + "=" + value);
  auto scene = load_scene_or_default(source_.scene_path, sets, source_.allow_paths);
  if (!scene) return scene;
  // Edited curves: the tables themselves (no file until the overrides are saved).
  for (const auto& [text, lut] : curve_edits_) {
    const EditKey key = EditKey::parse(text);
    bool found = false;
    for (Material& m : scene->materials) {
      if (key.curve() == CurveKind::kNone || m.name != key.material()) continue;
      (key.curve() == CurveKind::kIntensity ? m.intensity_lut : m.speed_gain_lut) = lut;
      found = true;
    }
    if (!found) return make_error("curve " + text + ": no such material curve (materials.NAME.intensity_lut or speed_gain_lut)");
  }
  return scene;
}

Status TuneSession::set_curve(const std::string& key, const Lut& lut) {
  const std::map<std::string, Lut> before = curve_edits_;
  if (lut.empty()) curve_edits_.erase(key);
  else curve_edits_[key] = lut;
  const Status s = rebuild(edits_, ViewRestart{true, false}, true, load(edits_));
  if (!s) curve_edits_ = before;
  return s;
}

Status TuneSession::fail(const Error& e) {
  last_error_ = e.message;
  return e;
}

// The first view: the scene's, with the source's flags; then the session's view of the new scene
// (rebuilt_view: the camera as the workspace sees it, since the new view starts with no pose; the
// world camera kept was carried twice, and once the haptic loop restarted its view the picture
// stayed moved by the old pose, Home included, docs/fourd.md).
Status TuneSession::rebuild(const std::map<std::string, std::string>& edits, ViewRestart restart, bool keep_tiles,
                            Result<Scene> scene) {
  // Watch the scene's files even when it fails to load, so fixing it triggers a reload.
  const Scene& watched = scene ? scene.value() : (renderer_ ? renderer_->scene() : Scene{});
  watch_.set_files(reload_dependencies(watched, source_.scene_path, source_.renderer.glsl_root));
  if (!scene) return fail(scene.error());
  auto view = view_ ? rebuilt_view(*view_, scene.value(), restart) : make_view(scene.value(), source_.show);
  if (!view) return fail(view.error());
  RendererOptions options = source_.renderer;
  options.view = view.value();
  if (keep_tiles) options.reuse_tiles_from = renderer_.get();  // edits only: shaders unchanged
  auto fresh = open_renderer(scene.value(), options);
  if (!fresh) return fail(fresh.error());
  renderer_ = std::move(fresh.value());
  view_ = std::move(view.value());
  if (edits != edits_) ++edits_generation_;  // once per rebuild, not per frame
  edits_ = edits;
  last_error_.clear();
  ++generation_;
  return ok_status();
}

Status TuneSession::set(const std::string& key, const std::string& value) {
  auto edits = edits_;
  edits[key] = value;
  // The probe restarts from the scene's state (so `render --overrides` reproduces a console
  // session); the window's haptic loop sets it again every frame anyway.
  return rebuild(edits, ViewRestart{true, EditKey::parse(key).camera()}, true, load(edits));
}

Status TuneSession::reload() { return rebuild(edits_, {}, false, load(edits_)); }

bool TuneSession::reload_if_changed() {
  if (!watch_.changed()) return false;
  // Baked Gabor tiles depend on the material, the seed and the shaders: when no shader file
  // changed, the new renderer shares the tiles of materials whose Gabor values are unchanged
  // (a re-bake costs ~0.5 s on llvmpipe; a saved edit should be on screen sooner).
  bool shader_changed = false;
  for (const std::string& f : watch_.last_changed()) {
    const std::string ext = std::filesystem::path(f).extension().string();
    shader_changed |= ext == ".glsl" || ext == ".vert" || ext == ".frag" || ext == ".comp";
  }
  (void)rebuild(edits_, {}, !shader_changed, load(edits_));  // outcome in last_error_
  return true;
}

Status TuneSession::save_overrides(const std::string& path) const {
  const std::string scene_name = source_.scene_path.empty() ? "the built-in default scene" : source_.scene_path;
  std::string target = path;
  if (target.empty()) {
    if (source_.scene_path.empty())
      return make_error("save: the built-in default scene has no file; give the override file's name");
    target = overrides_path_for(source_.scene_path);
  }
  return save_overrides_file(target, edits_, curve_edits_, scene_name);
}

}  // namespace ps
