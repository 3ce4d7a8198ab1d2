// A tuning session on the render thread: the scene (file + --set overrides + the session's
// own edits), its view (render/view.h) and the Renderer drawing it, live reload and the override
// file.
//
// Reload policy: a change (file edit or `set`) builds a NEW Renderer from the re-loaded
// scene and swaps it in only if scene parsing and every shader build succeeded; otherwise the
// old Renderer keeps running and last_error() holds the one-line reason (file:line for shader
// and scene errors). The view is the session's: the new Renderer draws the session's view of the
// new scene (rebuilt_view), nothing is copied from the old Renderer. A file reload keeps the
// probe's position and velocity and the camera (orbit); `set` keeps the camera unless it sets a
// camera.* key and restarts the probe from the scene; the flags are always kept. Needs a current
// context.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/result.h"
#include "render/renderer.h"
#include "tune/file_watch.h"

namespace ps {

struct TuneSource {
  std::string scene_path;               // empty: the built-in default scene
  std::vector<std::string> overrides;   // "KEY=VALUE", in command-line order (--set, --overrides lines)
  RendererOptions renderer;
  std::vector<std::string> allow_paths;  // --allow-path (scene/path_policy.h)
  ViewFlags show;  // what the session's first view shows (run's --show-probe, --show-device)
};

class TuneSession {
 public:
  static Result<std::unique_ptr<TuneSession>> open(TuneSource source);
  // As open(), starting from `scene` already loaded from `source` (the caller needed it before
  // the context existed), so the scene file is not parsed twice.
  static Result<std::unique_ptr<TuneSession>> open(TuneSource source, Scene scene);

  Renderer& renderer() { return *renderer_; }
  const Renderer& renderer() const { return *renderer_; }
  // The session's view, which renderer() draws (the window's keys toggle its flags and orbit its
  // camera); after a rebuild, the new scene's view per the reload policy (a new object).
  View& view() { return *view_; }
  const View& view() const { return *view_; }

  // Edits one value (a --set KEY=VALUE) and rebuilds; on failure the edit is dropped and
  // the previous renderer stays.
  Status set(const std::string& key, const std::string& value);
  // Re-reads the scene and shaders from disk and rebuilds (keeps the last good on failure).
  Status reload();
  // Re-reads the scene and shaders if a watched file changed. Returns false if nothing
  // changed; otherwise the reload's outcome is in last_error() (empty = success).
  bool reload_if_changed();

  const std::string& last_error() const { return last_error_; }
  const std::map<std::string, std::string>& edits() const { return edits_; }
  const FileWatch& watch() const { return watch_; }
  int generation() const { return generation_; }  // +1 per successful (re)build
  // +1 per successful rebuild that changed edits() (a `set`; not a reload, nor a curve edit): what
  // a frame compares to know whether the edits moved, instead of the edits themselves.
  std::uint64_t edits_generation() const { return edits_generation_; }
  const std::string& scene_path() const { return source_.scene_path; }

  // Replaces a material's curve by a lookup table and rebuilds; `key` is
  // "materials.NAME.intensity_lut" or "materials.NAME.speed_gain_lut"; an empty table drops the
  // edit (the scene's curve again). On failure the edit is dropped and the previous renderer stays.
  Status set_curve(const std::string& key, const Lut& lut);
  const std::map<std::string, Lut>& curve_edits() const { return curve_edits_; }

  // Writes edits() and curve_edits() as an override file (atomically), each edited curve as a
  // table file next to it (tune/overrides_file.h); path empty = overrides_path_for(scene).
  Status save_overrides(const std::string& path = {}) const;

 private:
  TuneSession() = default;
  Result<Scene> load(const std::map<std::string, std::string>& edits) const;
  Status rebuild(const std::map<std::string, std::string>& edits, ViewRestart restart, bool keep_tiles,
                 Result<Scene> scene);
  Status fail(const Error& e);  // last_error() = e's message

  TuneSource source_;
  std::shared_ptr<View> view_;  // what renderer_ draws (RendererOptions::view)
  std::unique_ptr<Renderer> renderer_;
  std::map<std::string, std::string> edits_;
  std::map<std::string, Lut> curve_edits_;  // applied to the loaded scene in load()
  FileWatch watch_;
  std::string last_error_;
  int generation_ = 0;
  std::uint64_t edits_generation_ = 0;
};

}  // namespace ps
