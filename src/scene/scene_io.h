// Scene files: TOML (toml++), human-edited with comments; format in docs/scene-format.md.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/result.h"
#include "scene/scene.h"

namespace ps {

// Larger scene files are refused before reading (hand-edited scenes are a few KiB).
inline constexpr std::uintmax_t kMaxSceneFileBytes = 1u << 20;

// Parses scene text. `source_name` is used in messages ("<source_name>:<line>: what").
// Relative file references (meshes, textures) resolve against `base_dir`.
// `overrides` are "KEY=VALUE" strings (the CLI's --set), applied before validation; VALUE is a
// TOML value (number, string in quotes or bare word, array like [1,2,3]). A relative file
// value in an override (intensity_lut, mesh_file, a button's "scene:FILE", ...) was written by
// the user where they stand, so it resolves against the working directory, not `base_dir`
// (anchor_override_path; docs/scene-format.md "Relative paths").
// Errors: syntax -> "file:line: ..."; unknown key -> "file:line: unknown key 'x' in [t]; did you
// mean 'y'?"; unknown --set key -> "--set a.b.c: unknown key; close matches: ...";
// bad values (NaN, negative radius, ...) -> "file:line: ...".
// The files the scene references must lie in `base_dir`'s tree, the shipped data or one of
// `allow_paths` (scene/path_policy.h); values from `overrides` are the user's and are not confined.
Result<Scene> parse_scene(std::string_view text, const std::string& source_name,
                          const std::string& base_dir,
                          const std::vector<std::string>& overrides = {},
                          const std::vector<std::string>& allow_paths = {});

// Reads `path` and parses it (missing file -> "path: cannot open scene file: <reason>").
Result<Scene> load_scene(const std::string& path, const std::vector<std::string>& overrides = {},
                         const std::vector<std::string>& allow_paths = {});

// `path`, or the built-in default scene (scenes/default.toml, embedded) when `path` is empty;
// the one place that rule is written. Messages about the default scene name kDefaultSceneName.
inline constexpr const char* kDefaultSceneName = "<built-in default scene>";
Result<Scene> load_scene_or_default(const std::string& path, const std::vector<std::string>& overrides = {},
                                    const std::vector<std::string>& allow_paths = {});

// "KEY=VALUE" with a relative file value (a key that names a file: *_lut, mesh_file,
// albedo_texture, heightmap, a button's action "scene:FILE") made absolute against `base_dir`;
// any other text is returned unchanged. parse_scene anchors every override at the working
// directory; read_overrides anchors the lines of an override file at that file's directory first.
std::string anchor_override_path(const std::string& text, const std::string& base_dir);

// The embedded copy of scenes/default.toml (compiled in so `render` works with no --scene).
std::string_view default_scene_text();

// Base dir for the relative paths of default_scene_text(): share/pseudoshadow/scenes found from
// the binary's own location (core/install_layout.h; in the build tree a link to the source
// tree's scenes/, in an install the shipped copy). Parse the embedded scene
// with parse_scene(default_scene_text(), "<embedded default>", default_scene_base_dir(), sets).
std::string default_scene_base_dir();

}  // namespace ps
