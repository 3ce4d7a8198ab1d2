// run's 4D turn keys (docs/fourd.md): 1 ... 6 turn the fourd surfaces 5 degrees in the xy ... zw
// plane, Shift+1 ... 6 back; the edits name each fourd surface's rotation key with the new
// angle, and scenes without a fourd surface get none. No window.
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include "app/window/window_input.h"
#include "scene/scene_io.h"

namespace ps {
namespace {

TEST(FourdKeysTest, DigitKeysTurnTheFourdSurfacesInTheirPlane) {
  WindowInput in;
  handle_key(in, GLFW_KEY_3, GLFW_PRESS, 0);                  // xw, +1
  handle_key(in, GLFW_KEY_3, GLFW_PRESS, 0);                  // xw, +1
  handle_key(in, GLFW_KEY_6, GLFW_PRESS, GLFW_MOD_SHIFT);     // zw, -1
  handle_key(in, GLFW_KEY_6, GLFW_REPEAT, GLFW_MOD_SHIFT);    // a repeat is not a step
  EXPECT_EQ(in.turn4[2], 2);
  EXPECT_EQ(in.turn4[5], -1);
  EXPECT_EQ(in.turn4[0] + in.turn4[1] + in.turn4[3] + in.turn4[4], 0);
  auto scene = load_scene(std::string(PS_SOURCE_DIR) + "/scenes/fourd/flat_torus.toml");
  ASSERT_TRUE(scene) << scene.error().message;
  const auto edits = fourd_turn_edits(scene.value(), in.turn4);
  ASSERT_EQ(edits.size(), 2u);
  EXPECT_EQ(edits[0].first, "surfaces.0.fourd_rotation_xw_deg");
  EXPECT_EQ(edits[0].second, "40");  // the scene's 30 + 2 x 5
  EXPECT_EQ(edits[1].first, "surfaces.0.fourd_rotation_zw_deg");
  EXPECT_EQ(edits[1].second, "-5");
  // The edits load: the scene with them is the surface turned.
  std::vector<std::string> sets;
  for (const auto& [k, v] : edits) sets.push_back(k + "=" + v);
  auto turned = load_scene(std::string(PS_SOURCE_DIR) + "/scenes/fourd/flat_torus.toml", sets);
  ASSERT_TRUE(turned) << turned.error().message;
  EXPECT_EQ(turned->surfaces[0].fourd.rotation_deg[2], 40.0);
  auto plain = load_scene(std::string(PS_SOURCE_DIR) + "/scenes/default.toml");
  ASSERT_TRUE(plain) << plain.error().message;
  EXPECT_TRUE(fourd_turn_edits(plain.value(), in.turn4).empty());
}

}  // namespace
}  // namespace ps
