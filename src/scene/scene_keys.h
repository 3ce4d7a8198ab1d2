// Known keys of every scene table, plus the "did you mean" helpers built on them.
// This is the ONE list of key names: the converter's TableReader asserts that every key it
// reads is listed here and that every listed key was read, and the unknown-key check and the
// --set path check use the same list, so the three cannot drift apart.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace ps::scene_detail {

// kHaptic is [materials.NAME.haptic]; kHapticWave one [[materials.NAME.haptic.texture]] entry.
enum class Section { kRoot, kCamera, kLight, kProbe, kRender, kMaterial, kHaptic, kHapticWave, kSurface, kField, kBody, kButton, kNavigation };

std::span<const std::string_view> known_keys(Section section);

// The unit of a key's value for labels ("mm", "mm/s", "deg", "Hz", "px"), from its leaf name
// (the suffix _mm, _deg, _hz, _n, _n_per_mm, _n_s_per_mm, _mm_s, or a known name: position,
// velocity, lambda_min, ...); "" when
// unitless. docs/scene-format.md has the same units in its tables.
std::string_view key_unit(std::string_view leaf);

// Levenshtein distance (insert, delete, substitute all cost 1).
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidates closest to `key` (ties, at most 3) if within a small edit distance.
std::vector<std::string_view> close_matches(std::string_view key,
                                            std::span<const std::string_view> candidates);

// "a, b, c"
std::string join(std::span<const std::string_view> items, std::string_view separator = ", ");

}  // namespace ps::scene_detail
