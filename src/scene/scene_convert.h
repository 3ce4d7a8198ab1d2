// Converters from the TOML tables of a scene file to the Scene model (internal to ps_scene).
#pragma once

#include <toml++/toml.h>

#include "core/result.h"
#include "scene/scene.h"
#include "scene/scene_reader.h"

namespace ps::scene_detail {

// Each converter checks unknown keys, reads every known key (absent keys keep the defaults of
// scene.h) and validates ranges. `table` may be null (section absent).
Status read_camera(const ParseContext& ctx, const toml::table* table, Camera& out);
Status read_light(const ParseContext& ctx, const toml::table* table, Light& out);
Status read_navigation(const ParseContext& ctx, const toml::table* table, Navigation& out);
Status read_probe(const ParseContext& ctx, const toml::table* table, Probe& out);
Status read_render(const ParseContext& ctx, const toml::table* table, RenderSettings& out);
Status read_material(const ParseContext& ctx, const toml::table& table, const std::string& name,
                     Material& out);
// [materials.NAME.haptic] (`table` may be null: defaults); `path` is "materials.NAME.haptic".
Status read_haptic(const ParseContext& ctx, const toml::table* table, const std::string& path,
                   HapticMaterial& out);
// `material_names` resolves Surface::material to Surface::material_index.
Status read_surface(const ParseContext& ctx, const toml::table& table, int index,
                    const std::vector<std::string>& material_names, Surface& out);

// The fourd_* keys of a surface (scene_fourd.cpp); they apply only to type = "fourd".
void read_fourd_keys(TableReader& r, Surface& out);

// [[fields]] #index and [[bodies]] #index (scene_world.cpp); a body's material resolves like a
// surface's (empty: material 0).
Status read_field(const ParseContext& ctx, const toml::table& table, int index, Field& out);
Status read_body(const ParseContext& ctx, const toml::table& table, int index,
                 const std::vector<std::string>& material_names, Body& out);

// [[buttons]] #index (scene_world.cpp): the action resolved ("scene:FILE" to an existing file's
// absolute path), the size checked against the probe's diameter, the material like a body's.
Status read_button(const ParseContext& ctx, const toml::table& table, int index,
                   const std::vector<std::string>& material_names, double probe_radius_mm, Button& out);

// Reads the files named by the root's `include` (recursively) into ctx.included
// (scene_include.cpp); errors carry the including line or the included file's own line.
Status resolve_includes(toml::table& root, ParseContext& ctx);

// Applies one "KEY=VALUE" override to the parsed document and records it in ctx.overridden.
Status apply_override(toml::table& root, const std::string& text, ParseContext& ctx);

}  // namespace ps::scene_detail
