// The prepare room (src/prepare): what a world prepares before its first frame, checked against
// the world itself. Field's floor map (prepare/field_map.h) against a grid search of the force
// its haptic scene feels. No GL.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "prepare/field_map.h"
#include "scene/scene_io.h"
#include "world/haptic_scene.h"

namespace ps::world {
namespace {

std::string universe(const std::string& name) { return std::string(PS_SOURCE_DIR) + "/scenes/universe/" + name; }

// Field's floor map: its darkest pixel away from the charges is the weak spot a grid search of
// the force finds in the same plane (within 2 map texels: the map's 256 texels over 200 mm and
// its 8-bit colour steps), and its brightest pixels are near a charge.
TEST(FieldMapTest, FieldsMapShowsItsWeakSpot) {
  auto scene = load_scene(universe("field.toml"));
  ASSERT_TRUE(scene) << scene.error().message;
  const Surface& floor = scene->surfaces[0];
  ASSERT_TRUE(floor.field_map);
  const Image im = field_map_image(scene.value(), floor);
  ASSERT_EQ(im.width, kFieldMapSize);
  const double side = std::max(floor.box_size_mm.x, floor.box_size_mm.y), texel = side / kFieldMapSize;
  const glm::dvec2 corner = glm::dvec2(floor.center) - 0.5 * glm::dvec2(side);
  double z = 0.0;
  for (const Field& c : scene->fields) z += c.position.z / 3.0;
  auto near_charge = [&](const glm::dvec3& p) {
    for (const Field& c : scene->fields)
      if (glm::length(glm::dvec2(p) - glm::dvec2(c.position)) < 8.0) return true;
    return false;
  };
  // Darkest map pixel (sum of channels: the map runs dark blue -> yellow) inside the floor.
  double darkest = 1e9;
  glm::dvec3 dark_at(0.0);
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) {
      const glm::dvec3 p(corner.x + (x + 0.5) * texel, corner.y + (im.height - 1 - y + 0.5) * texel, z);
      if (near_charge(p) || std::abs(p.y - floor.center.y) > 0.5 * floor.box_size_mm.y) continue;
      const double v = im.at(x, y, 0) + im.at(x, y, 1) + im.at(x, y, 2);
      if (v < darkest) {
        darkest = v;
        dark_at = p;
      }
    }
  auto hs = HapticScene::build(scene.value());
  ASSERT_TRUE(hs);
  double weakest = 1e9;
  glm::dvec3 weak_at(0.0);
  for (double x = -50.0; x <= 50.0; x += 0.25)
    for (double y = -40.0; y <= 60.0; y += 0.25) {
      const glm::dvec3 p(x, y, z);
      if (near_charge(p)) continue;
      const double f = glm::length(hs->fields().force_n(p, glm::dvec3(0.0), 0.0));
      if (f < weakest) {
        weakest = f;
        weak_at = p;
      }
    }
  EXPECT_LT(glm::length(glm::dvec2(dark_at - weak_at)), 2.0 * texel + 0.25)
      << "map's darkest (" << dark_at.x << ", " << dark_at.y << "), weakest force (" << weak_at.x << ", " << weak_at.y << ")";
}

}  // namespace
}  // namespace ps::world
