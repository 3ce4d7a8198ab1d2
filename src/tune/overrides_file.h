// Override files: the values edited in a tuning session, saved next to the scene as
// `<scene>.overrides.toml`. Format: one dotted `KEY = VALUE` line per changed key, exactly a
// `--set KEY=VALUE` (docs/tuning.md), plus `#` comments. Only the changed keys are written, so
// the scene file stays the reviewed source and the overrides are one visible diff on top.
// `--overrides FILE` (every command with a scene) applies them where it stands among the --set
// options, so a later --set wins over the file and a later file over an earlier --set.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/result.h"
#include "scene/lut.h"

namespace ps {

// "scenes/a.toml" -> "scenes/a.overrides.toml" (the extension is replaced, not appended).
std::string overrides_path_for(const std::string& scene_path);

// VALUE as written: numbers, booleans, arrays and quoted strings verbatim; a bare word
// (exact_max) is quoted so every line is also valid TOML.
std::string override_value_text(const std::string& value);

// The file text for `edits` (key -> value), sorted by key.
std::string format_overrides(const std::map<std::string, std::string>& edits,
                             const std::string& scene_name);

// Curves edited as lookup tables (the panel's curve editor): key "materials.NAME.intensity_lut"
// or "materials.NAME.speed_gain_lut" -> the table. Saved as table files NEXT TO the override file
// (curve_file_for) and one line each, KEY = "FILE" with FILE relative to the override file (a
// relative file value in an override file resolves against that file's directory,
// docs/scene-format.md "Relative paths"), so the override file with its tables is what
// `--overrides` reads back from any working directory, and the tables are plain files to review.
std::string curve_file_for(const std::string& overrides_path, const std::string& key);

// Writes the tables of `curves` (each atomically), then the override file for `edits` plus one
// line per curve (atomically). A curve key must be a material's *_lut key (asserted).
Status save_overrides_file(const std::string& path, const std::map<std::string, std::string>& edits,
                           const std::map<std::string, Lut>& curves, const std::string& scene_name);

// Reads an override file into "KEY=VALUE" strings for parse_scene/load_scene, a relative file
// value made absolute against the file's own directory (anchor_override_path).
// Errors: "<path>: cannot open override file: <reason>", "<path>:<line>: expected KEY = VALUE".
Result<std::vector<std::string>> read_overrides(const std::string& path);

}  // namespace ps
