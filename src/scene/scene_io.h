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
// TOML value (number, string in quotes or bare word, array like [1,2,3]).
// Errors: syntax -> "file:line: ..."; unknown key -> "file:line: unknown key 'x' in [t]; did you
// mean 'y'?"; unknown --set key -> "--set a.b.c: unknown key; close matches: ...";
// bad values (NaN, negative radius, ...) -> "file:line: ...".
Result<Scene> parse_scene(std::string_view text, const std::string& source_name,
                          const std::string& base_dir,
                          const std::vector<std::string>& overrides = {});

// Reads `path` and parses it (missing file -> "path: cannot open scene file: <reason>").
Result<Scene> load_scene(const std::string& path, const std::vector<std::string>& overrides = {});

// `path`, or the built-in default scene (scenes/default.toml, embedded) when `path` is empty;
// the one place that rule is written. Messages about the default scene name kDefaultSceneName.
inline constexpr const char* kDefaultSceneName = "<built-in default scene>";
Result<Scene> load_scene_or_default(const std::string& path, const std::vector<std::string>& overrides = {});

// The embedded copy of scenes/default.toml (compiled in so `render` works with no --scene).
std::string_view default_scene_text();

// Base dir for the relative paths of default_scene_text(): share/pseudoshadow/scenes found from
// the binary's own location (core/install_layout.h; in the build tree a link to the source
// tree's scenes/, in an install the shipped copy). Parse the embedded scene
// with parse_scene(default_scene_text(), "<embedded default>", default_scene_base_dir(), sets).
std::string default_scene_base_dir();

}  // namespace ps
