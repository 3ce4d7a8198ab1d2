#include "render/aov.h"

#include <cstddef>
#include <iterator>

namespace ps {

namespace {

// One row per Aov, in enum order (checked below).
constexpr AovInfo kAovTable[] = {
    {Aov::kIntensity, "intensity", AovSource::kSurfaceAov, 0},
    {Aov::kDistance, "distance", AovSource::kSurfaceAov, 1},
    {Aov::kTexture, "texture", AovSource::kSurfaceAov, 2},
    {Aov::kNormal, "normal", AovSource::kNormal, 0},
    {Aov::kDisplacement, "displacement", AovSource::kDisplacement, 0},
};
constexpr bool aov_table_in_enum_order() {
  for (std::size_t i = 0; i < std::size(kAovTable); ++i)
    if (static_cast<std::size_t>(kAovTable[i].aov) != i) return false;
  return std::size(kAovTable) == static_cast<std::size_t>(Aov::kDisplacement) + 1;
}
static_assert(aov_table_in_enum_order(), "kAovTable: one row per Aov, in enum order");

}  // namespace

const AovInfo& aov_info(Aov aov) { return kAovTable[static_cast<std::size_t>(aov)]; }

const std::vector<std::string>& aov_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const AovInfo& e : kAovTable) n.emplace_back(e.name);
    return n;
  }();
  return names;
}

Result<Aov> parse_aov(const std::string& name) {
  for (const AovInfo& e : kAovTable)
    if (name == e.name) return e.aov;
  std::string list;
  for (const AovInfo& e : kAovTable) list += (list.empty() ? "" : ", ") + std::string(e.name);
  return make_error("unknown AOV '" + name + "' (known: " + list + ")");
}

}  // namespace ps
