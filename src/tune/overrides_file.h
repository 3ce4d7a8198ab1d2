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

namespace ps {

// "scenes/a.toml" -> "scenes/a.overrides.toml" (the extension is replaced, not appended).
std::string overrides_path_for(const std::string& scene_path);

// VALUE as written: numbers, booleans, arrays and quoted strings verbatim; a bare word
// (exact_max) is quoted so every line is also valid TOML.
std::string override_value_text(const std::string& value);

// The file text for `edits` (key -> value), sorted by key.
std::string format_overrides(const std::map<std::string, std::string>& edits,
                             const std::string& scene_name);

// Reads an override file into "KEY=VALUE" strings for parse_scene/load_scene.
// Errors: "<path>: cannot open override file: <reason>", "<path>:<line>: expected KEY = VALUE".
Result<std::vector<std::string>> read_overrides(const std::string& path);

}  // namespace ps
