// [[fields]], [[bodies]] and [[buttons]]: values, exact "file:line: message" errors, --set reaching them.
#include <gtest/gtest.h>

#include "scene_test_util.h"

namespace ps {
namespace {

using test::error_of;
using test::parse;

// kMinimalScene has 6 lines; appended text starts at line 7.
std::string with(const std::string& extra) { return std::string(test::kMinimalScene) + extra; }

TEST(SceneWorldTest, ReadsEveryFieldKindAndABody) {
  Result<Scene> scene = parse(with(R"(
[[fields]]
type = "gravity"
acceleration_mm_s2 = [0, 0, -5000]

[[fields]]
type = "uniform"
force_n = [0.5, 0, 0]
fluctuation_n = [0, 0.25, 0]
frequency_hz = 2
center = [0, 0, 10]
size_mm = [40, 40, 20]

[[fields]]
type = "viscous"
viscosity_n_s_per_mm = 0.01
center = [30, 0, 10]
size_mm = [20, 20, 20]
rotation_deg = [0, 0, 45]

[[fields]]
type = "charge"
position = [-20, 0, 10]
charge_n_mm2 = -300
softening_mm = 3

[[bodies]]
mass_g = 80
spring_n_per_mm = 0.2
rest_length_mm = 25
radius_mm = 5
material = "wood"
position = [0, 0, -10]
floor_z_mm = -40
restitution = 0.5
time_scale = 0.5
substeps = 8
)"));
  ASSERT_TRUE(scene) << scene.error().message;
  ASSERT_EQ(scene->fields.size(), 4u);
  EXPECT_EQ(scene->fields[0].type, FieldType::kGravity);
  EXPECT_EQ(scene->fields[0].acceleration_mm_s2, glm::dvec3(0, 0, -5000));
  const Field& u = scene->fields[1];
  EXPECT_EQ(u.type, FieldType::kUniform);
  EXPECT_TRUE(u.bounded);
  EXPECT_EQ(u.fluctuation_n, glm::dvec3(0, 0.25, 0));
  EXPECT_EQ(u.frequency_hz, 2.0);
  EXPECT_EQ(u.size_mm, glm::dvec3(40, 40, 20));
  EXPECT_EQ(scene->fields[2].viscosity_n_s_per_mm, 0.01);
  EXPECT_EQ(scene->fields[2].rotation_deg.z, 45.0);
  EXPECT_EQ(scene->fields[3].charge_n_mm2, -300.0);
  EXPECT_EQ(scene->fields[3].softening_mm, 3.0);
  EXPECT_EQ(scene->fields[3].line, 27);
  ASSERT_EQ(scene->bodies.size(), 1u);
  const Body& b = scene->bodies[0];
  EXPECT_EQ(b.mass_g, 80.0);
  EXPECT_EQ(b.rest_length_mm, 25.0);
  EXPECT_EQ(b.floor_z_mm, -40.0);
  EXPECT_EQ(b.time_scale, 0.5);
  EXPECT_EQ(b.substeps, 8);
  EXPECT_EQ(b.line, 33);
}

TEST(SceneWorldTest, ASceneWithoutFieldsOrBodiesHasNone) {
  Result<Scene> scene = parse(test::kMinimalScene);
  ASSERT_TRUE(scene) << scene.error().message;
  EXPECT_TRUE(scene->fields.empty());
  EXPECT_TRUE(scene->bodies.empty());
}

TEST(SceneWorldTest, BadFieldsAndBodiesNameFileAndLine) {
  EXPECT_EQ(error_of(with("[[fields]]\ntype = \"charge\"\nposition = [0, 0, 0]\ncharg_n_mm2 = 5\n")),
            "s.toml:10: unknown key 'charg_n_mm2' in [[fields]] #0; did you mean 'charge_n_mm2'?");
  EXPECT_EQ(error_of(with("[[fields]]\nforce_n = [1, 0, 0]\n")),
            "s.toml:7: 'type' is required: one of \"gravity\", \"uniform\", \"viscous\", \"charge\"");
  EXPECT_EQ(error_of(with("[[fields]]\ntype = \"viscous\"\nviscosity_n_s_per_mm = 0.01\n")),
            "s.toml:7: 'size_mm' is required for a viscous field: the box region where it acts "
            "(centre 'center')");
  EXPECT_EQ(error_of(with("[[fields]]\ntype = \"viscous\"\nsize_mm = [1, 1, 1]\nviscosity_n_s_per_mm = -0.1\n")),
            "s.toml:10: 'viscosity_n_s_per_mm' must be in [0, 1] (got -0.1)");
  EXPECT_EQ(error_of(with("[[fields]]\ntype = \"gravity\"\nforce_n = [1, 0, 0]\n")),
            "s.toml:9: 'force_n' applies only to type = \"uniform\"");
  EXPECT_EQ(error_of(with("[[fields]]\ntype = \"charge\"\nposition = [1, 2, 3]\ncharge_n_mm2 = 5\n\n"
                          "[[fields]]\ntype = \"charge\"\nposition = [1, 2, 3]\ncharge_n_mm2 = -2\n")),
            "s.toml:12: [[fields]] #1: a second charge at the position of [[fields]] #0 (line 7); merge them "
            "into one charge (their sum)");
  EXPECT_EQ(error_of(with("[[bodies]]\nmass_g = -5\n")),
            "s.toml:8: 'mass_g' must be in (0, 100000] (got -5)");
  EXPECT_EQ(error_of(with("[[bodies]]\nspring_n_per_mm = 0\n")),
            "s.toml:8: 'spring_n_per_mm' must be in (0, 100] (got 0)");
  EXPECT_EQ(error_of(with("[[bodies]]\nrestitution = 1.5\n")),
            "s.toml:8: 'restitution' must be in [0, 1] (got 1.5)");
  EXPECT_EQ(error_of(with("[[bodies]]\nmaterial = \"steel\"\n")),
            "s.toml:8: 'material' names unknown material 'steel'; defined materials: wood");
  EXPECT_EQ(error_of("fields = 3\n" + std::string(test::kMinimalScene)),
            "s.toml:1: 'fields' must be an array of tables ([[fields]])");
  std::string five;
  for (int i = 0; i < 5; ++i) five += "[[bodies]]\nmass_g = 10\n";
  EXPECT_EQ(error_of(with(five)), "s.toml:15: [[bodies]] #4: a scene has at most 4 bodies");
}

TEST(SceneWorldTest, SetReachesFieldsAndBodies) {
  const std::string text = with("[[fields]]\ntype = \"charge\"\nposition = [1, 2, 3]\ncharge_n_mm2 = 5\n"
                                "[[bodies]]\nmass_g = 10\n");
  Result<Scene> scene = parse(text, {"fields.0.charge_n_mm2=-7", "bodies.0.time_scale=0.25"});
  ASSERT_TRUE(scene) << scene.error().message;
  EXPECT_EQ(scene->fields[0].charge_n_mm2, -7.0);
  EXPECT_EQ(scene->bodies[0].time_scale, 0.25);
  EXPECT_EQ(error_of(text, {"bodies.3.mass_g=1"}),
            "--set bodies.3.mass_g: no body '3' (the scene has 1 bodies, numbered from 0)");
}

// A button: its keys, its action resolved (a scene file relative to the scene's directory, a
// flag numbered in order of first use), and the plate it adds to the surfaces (seen, not felt).
TEST(SceneWorldTest, ReadsButtonsAndAddsTheirPlates) {
  Result<Scene> scene = parse(with(R"(
[[buttons]]
center = [10, 0, 0]
size_mm = [30, 20]
stiffness_n_per_mm = 0.3
travel_mm = 2
action = "scene:default.toml"

[[buttons]]
center = [-30, 0, 0]
action = "flag:light"
visible = false

[[buttons]]
center = [-70, 0, 0]
action = "flag:light"
)"));
  ASSERT_TRUE(scene) << scene.error().message;
  ASSERT_EQ(scene->buttons.size(), 3u);
  const Button& b = scene->buttons[0];
  EXPECT_EQ(b.size_mm, glm::dvec2(30, 20));
  EXPECT_EQ(b.stiffness_n_per_mm, 0.3);
  EXPECT_EQ(b.travel_mm, 2.0);
  EXPECT_EQ(b.action_kind, ButtonActionKind::kScene);
  EXPECT_EQ(b.action_target, test::scenes_dir() + "/default.toml");
  EXPECT_EQ(b.line, 8);
  EXPECT_EQ(scene->buttons[1].action_kind, ButtonActionKind::kFlag);
  EXPECT_EQ(scene->buttons[1].flag, 0);
  EXPECT_EQ(scene->buttons[2].flag, 0);  // the same flag
  EXPECT_EQ(scene->flags, std::vector<std::string>{"light"});
  ASSERT_EQ(scene->surfaces.size(), 4u);  // the file's plane and three plates
  const Surface& plate = scene->surfaces[1];
  EXPECT_EQ(plate.button, 0);
  EXPECT_EQ(plate.type, SurfaceType::kBox);
  EXPECT_FALSE(plate.touchable);
  EXPECT_TRUE(plate.visible);
  EXPECT_EQ(plate.box_size_mm, glm::dvec3(30, 20, 1));
  EXPECT_NEAR(plate.center.z + 0.5 * plate.box_size_mm.z, 0.25, 1e-12);  // 0.25 mm proud of the face
  EXPECT_FALSE(scene->surfaces[2].visible);
  EXPECT_EQ(scene->surfaces[0].button, -1);
}

TEST(SceneWorldTest, BadButtonsNameFileAndLine) {
  EXPECT_EQ(error_of(with("[[buttons]]\ncenter = [0, 0, 0]\n")),
            "s.toml:7: 'action' is required: what the button does when pushed past its travel, \"scene:FILE\" "
            "(switch to that scene) or \"flag:NAME\" (toggle a named flag)");
  EXPECT_EQ(error_of(with("[[buttons]]\naction = \"open:door\"\n")),
            "s.toml:8: 'action' 'open:door' is not \"scene:FILE\" or \"flag:NAME\"");
  EXPECT_EQ(error_of(with("[[buttons]]\naction = \"scene:no_such_world.toml\"\n")),
            "s.toml:8: 'action' scene file not found: " + test::scenes_dir() + "/no_such_world.toml");
  EXPECT_EQ(error_of(with("[[buttons]]\naction = \"flag:x\"\nsize_mm = [10, 40]\n")),
            "s.toml:9: 'size_mm' is narrower than the probe (16 mm across): the probe could not push it "
            "in; make it at least that wide");
  EXPECT_EQ(error_of(with("[[buttons]]\naction = \"flag:x\"\nstiffness_n_per_mm = -1\n")),
            "s.toml:9: 'stiffness_n_per_mm' must be in (0, 100] (got -1)");
  EXPECT_EQ(error_of(with("[[buttons]]\naction = \"flag:x\"\ntravel = 2\n")),
            "s.toml:9: unknown key 'travel' in [[buttons]] #0; did you mean 'travel_mm'?");
  EXPECT_EQ(error_of(with("[[buttons]]\naction = \"flag:x\"\nmaterial = \"brass\"\n")),
            "s.toml:9: 'material' names unknown material 'brass'; defined materials: wood");
  std::string many;
  for (int i = 0; i < 17; ++i) many += "[[buttons]]\naction = \"flag:f\"\n";
  EXPECT_EQ(error_of(with(many)), "s.toml:39: [[buttons]] #16: a scene has at most 16 buttons");
}

// Poly's bendable polygons (surfaces.N.deformable): the keys, and a spring constant of zero or
// below, a plane (too few vertices to dent) or a stretched surface refused at file:line.
TEST(SceneWorldTest, DeformableSurfacesAndTheirErrors) {
  Result<Scene> scene = parse(with("type = \"sphere\"\ndeformable = true\ndeform_base_n_per_mm = 0.1\n"
                                   "deform_neighbour_n_per_mm = 0.3\ndeform_max_mm = 4\n"),
                              {"surfaces.0.deform_mass_g=2"});
  ASSERT_TRUE(scene) << scene.error().message;
  const DeformParams& d = scene->surfaces[0].deform;
  EXPECT_TRUE(d.enabled);
  EXPECT_EQ(d.base_n_per_mm, 0.1);
  EXPECT_EQ(d.neighbour_n_per_mm, 0.3);
  EXPECT_EQ(d.max_mm, 4.0);
  EXPECT_EQ(d.mass_g, 2.0);
  EXPECT_EQ(error_of(with("type = \"sphere\"\ndeformable = true\ndeform_base_n_per_mm = 0\n")),
            "s.toml:9: 'deform_base_n_per_mm' must be in (0, 1000] (got 0)");
  EXPECT_EQ(error_of(with("type = \"torus\"\nradius_mm = 20\ndeformable = true\n"
                          "deform_neighbour_n_per_mm = -0.2\n")),
            "s.toml:10: 'deform_neighbour_n_per_mm' must be in (0, 1000] (got -0.2)");
  EXPECT_EQ(error_of(with("type = \"sphere\"\ndeformable = true\n"), {"surfaces.0.deform_base_n_per_mm=0"}),
            "--set surfaces.0.deform_base_n_per_mm: 'deform_base_n_per_mm' must be in (0, 1000] (got 0)");
  EXPECT_EQ(error_of(with("deformable = true\n")),
            "s.toml:7: 'deformable' needs a tessellated surface (mesh, sphere, torus or heightfield): a "
            "plane's or a box's few vertices cannot dent");
  EXPECT_EQ(error_of(with("type = \"sphere\"\nvisual_stretch = [2, 1, 1]\ndeformable = true\n")),
            "s.toml:9: 'deformable' cannot be combined with visual_stretch (the dent follows the drawn probe "
            "on the felt shape)");
}

TEST(SceneWorldTest, NavigationBoxAndItsErrors) {
  Result<Scene> none = parse(with(""));
  ASSERT_TRUE(none) << none.error().message;
  EXPECT_FALSE(none->navigation.enabled);
  Result<Scene> scene = parse("[navigation]\nbox_size_mm = [100, 80, 40]\n" + std::string(test::kMinimalScene),
                              {"navigation.speed_mm_s_per_mm=5"});
  ASSERT_TRUE(scene) << scene.error().message;
  EXPECT_TRUE(scene->navigation.enabled);
  EXPECT_EQ(scene->navigation.box_size_mm, glm::dvec3(100, 80, 40));
  EXPECT_EQ(scene->navigation.speed_mm_s_per_mm, 5.0);
  EXPECT_EQ(error_of("[navigation]\nbox_size_mm = [100, 0, 40]\n" + std::string(test::kMinimalScene)),
            "s.toml:2: 'box_size_mm' must be in (0, 100000] (got 0)");
  EXPECT_EQ(error_of("[navigation]\nspeed_mm_s_per_m = 3\n" + std::string(test::kMinimalScene)),
            "s.toml:2: unknown key 'speed_mm_s_per_m' in [navigation]; did you mean 'speed_mm_s_per_mm'?");
  EXPECT_EQ(error_of("navigation = 2\n" + std::string(test::kMinimalScene)),
            "s.toml:1: 'navigation' must be a table");
}

// A field map over a scene without charges (an empty charge list) is refused at the surface.
TEST(SceneWorldTest, FieldMapWithoutChargesNamesTheSurface) {
  EXPECT_EQ(error_of(with("type = \"box\"\nfield_map = true\n")),
            "s.toml:5: [[surfaces]] #0: 'field_map' shows the field of the scene's charges, and it has none; "
            "add a [[fields]] with type = \"charge\", or remove field_map");
  EXPECT_TRUE(parse(with("type = \"box\"\nfield_map = true\n[[fields]]\ntype = \"charge\"\nposition = [0, 0, 9]\n"
                         "charge_n_mm2 = 5\n")));
}

}  // namespace
}  // namespace ps
