// Closest points of the haptic scene against independent references: dense samples of each
// analytic surface's parametrisation, the renderer's own tessellation (same placement), and
// for meshes every triangle tested one by one.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "scene/mesh.h"
#include "world/haptic_scene.h"
#include "world/shapes.h"
#include "world_test_util.h"

namespace ps::world {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Points on a surface, sampled from its parametrisation (not from the code under test).
using Samples = std::vector<glm::dvec3>;

Samples sample_sphere(double r, int n) {
  Samples s;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j < 2 * n; ++j) {
      const double lat = kPi * i / n - kPi / 2, lon = kPi * j / n;
      s.push_back(r * glm::dvec3(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)));
    }
  return s;
}

Samples sample_torus(double big, double small, int n) {
  Samples s;
  for (int i = 0; i < 2 * n; ++i)
    for (int j = 0; j < n; ++j) {
      const double a = kPi * i / n, b = 2 * kPi * j / n;
      s.push_back({(big + small * std::cos(b)) * std::cos(a), (big + small * std::cos(b)) * std::sin(a), small * std::sin(b)});
    }
  return s;
}

Samples sample_box(glm::dvec3 size, int n) {  // the six faces, n x n each
  Samples s;
  const glm::dvec3 h = 0.5 * size;
  for (int axis = 0; axis < 3; ++axis)
    for (double side : {-1.0, 1.0})
      for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
          glm::dvec3 p;
          const int u = (axis + 1) % 3, v = (axis + 2) % 3;
          p[axis] = side * h[axis];
          p[u] = -h[u] + size[u] * i / n;
          p[v] = -h[v] + size[v] * j / n;
          s.push_back(p);
        }
  return s;
}

Samples sample_plane(glm::dvec2 size, int n) {
  Samples s;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) s.push_back({size.x * (double(i) / n - 0.5), size.y * (double(j) / n - 0.5), 0.0});
  return s;
}

// Largest distance from any surface point to its nearest sample: the sample-based distance
// can exceed the true one by at most this much.
struct Case {
  const char* name;
  Surface surface;
  Samples local_samples;
  double sample_spacing_mm;
};

std::vector<Case> cases() {
  const glm::dvec3 c{12.0, -7.0, 5.0}, rot{30.0, -20.0, 65.0};
  Surface plane = test::analytic(SurfaceType::kPlane, c, rot);
  plane.size_mm = {80.0, 50.0};
  Surface sphere = test::analytic(SurfaceType::kSphere, c, rot);
  sphere.radius_mm = 25.0;
  Surface box = test::analytic(SurfaceType::kBox, c, rot);
  box.box_size_mm = {40.0, 20.0, 30.0};
  Surface torus = test::analytic(SurfaceType::kTorus, c, rot);
  torus.radius_mm = 30.0;
  torus.minor_radius_mm = 8.0;
  // Spacing: plane 80/200; sphere pi r / 200 along a meridian; box 40/200; torus 2 pi R / 400.
  return {{"plane", plane, sample_plane(plane.size_mm, 200), 0.4},
          {"sphere", sphere, sample_sphere(25.0, 200), 0.4},
          {"box", box, sample_box(box.box_size_mm, 200), 0.2},
          {"torus", torus, sample_torus(30.0, 8.0, 200), 0.48}};
}

TEST(HapticSceneTest, AnalyticClosestPointMatchesDenseSamplesOfEveryShape) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-60.0, 60.0);
  for (const Case& k : cases()) {
    auto scene = HapticScene::build(test::scene_with(5.0, {k.surface}));
    ASSERT_TRUE(scene) << scene.error().message;
    const glm::dmat3 rot = euler_xyz_deg(k.surface.rotation_deg);
    Samples world;
    for (const glm::dvec3& s : k.local_samples) world.push_back(rot * s + k.surface.center);
    for (int i = 0; i < 200; ++i) {
      const glm::dvec3 p = k.surface.center + glm::dvec3(u(rng), u(rng), u(rng));
      double brute = 1e30;
      for (const glm::dvec3& s : world) brute = std::min(brute, glm::length(p - s));
      const Contact c = scene->closest(p, 1e9);
      ASSERT_TRUE(c.hit) << k.name;
      EXPECT_NEAR(c.distance_mm, glm::length(p - c.point), 1e-9) << k.name;
      // Samples lie on the surface, so no sample may be closer than the closest point (1e-9:
      // rounding of the rotation); the nearest sample is at most one spacing farther.
      EXPECT_LE(c.distance_mm, brute + 1e-9) << k.name << " at " << p.x << "," << p.y << "," << p.z;
      EXPECT_GE(c.distance_mm, brute - k.sample_spacing_mm) << k.name;
      // The normal is unit and lies along the offset from the point, outward for points
      // outside, inward for points inside (1e-9: double rounding). The finite plane keeps its
      // face normal (+-Z) also beside its rim, where the offset points sideways.
      EXPECT_NEAR(glm::length(c.normal), 1.0, 1e-9) << k.name;
      if (k.surface.type == SurfaceType::kPlane) {
        EXPECT_NEAR(std::abs(glm::dot(c.normal, rot * glm::dvec3(0, 0, 1))), 1.0, 1e-9);
      } else if (c.distance_mm > 1e-6) {
        EXPECT_NEAR(std::abs(glm::dot(c.normal, (p - c.point) / c.distance_mm)), 1.0, 1e-9) << k.name;
      }
    }
  }
}

TEST(HapticSceneTest, AnalyticShapesSitWhereTheRendererDrawsThem) {
  // The render mesh's vertices lie exactly on the analytic surface, so the haptic scene must
  // put them at distance ~0: checks centre, rotation order and sizes against scene/mesh.cpp.
  for (const Case& k : cases()) {
    if (k.surface.type == SurfaceType::kBox) continue;  // its render mesh comes with the box parser
    auto scene = HapticScene::build(test::scene_with(5.0, {k.surface}));
    ASSERT_TRUE(scene);
    auto mesh = build_surface_mesh(k.surface);
    ASSERT_TRUE(mesh) << mesh.error().message;
    for (const glm::vec3& v : mesh->positions) {
      // 1e-4 mm: the render mesh stores float positions (~1e-5 mm at 60 mm) after a rotation.
      EXPECT_LT(scene->closest(glm::dvec3(v), 1.0).distance_mm, 1e-4) << k.name;
    }
  }
}

TEST(ShapesTest, TriangleClosestPointMatchesDenseBarycentricSampling) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-10.0, 10.0);
  constexpr int kN = 300;  // samples per edge: spacing <= edge / 300
  for (int t = 0; t < 40; ++t) {
    const glm::dvec3 a{u(rng), u(rng), u(rng)}, b{u(rng), u(rng), u(rng)}, c{u(rng), u(rng), u(rng)};
    const double longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
    const glm::dvec3 p{u(rng), u(rng), u(rng)};
    double brute = 1e30;
    for (int i = 0; i <= kN; ++i)
      for (int j = 0; i + j <= kN; ++j) {
        const double s = double(i) / kN, r = double(j) / kN;
        brute = std::min(brute, glm::length(p - (a + s * (b - a) + r * (c - a))));
      }
    const TrianglePoint tp = closest_on_triangle(p, a, b, c);
    const glm::dvec3 from_bary = tp.barycentric.x * a + tp.barycentric.y * b + tp.barycentric.z * c;
    EXPECT_NEAR(glm::length(from_bary - tp.point), 0.0, 1e-9);  // consistent barycentrics
    EXPECT_LE(glm::length(p - tp.point), brute + 1e-9);
    EXPECT_GE(glm::length(p - tp.point), brute - longest / kN);  // one sample spacing
  }
}

void expect_bvh_matches_brute_force(const MeshBvh& bvh, glm::dvec3 lo, glm::dvec3 hi, int n) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> ux(lo.x, hi.x), uy(lo.y, hi.y), uz(lo.z, hi.z);
  MeshHit previous;
  for (int i = 0; i < n; ++i) {
    const glm::dvec3 p{ux(rng), uy(rng), uz(rng)};
    const MeshHit ref = bvh.closest_brute_force(p);
    const MeshHit h = bvh.closest(p, 1e9);
    ASSERT_TRUE(h.hit);
    // 1e-9 mm: both compute the same triangle distances in double; only ties may differ.
    EXPECT_NEAR(h.distance_mm, ref.distance_mm, 1e-9);
    // A hint (here the previous, unrelated query's hit) never changes the answer.
    EXPECT_NEAR(bvh.closest(p, 1e9, &previous).distance_mm, ref.distance_mm, 1e-9);
    EXPECT_NEAR(bvh.closest(p, 1e9, &h).distance_mm, ref.distance_mm, 1e-9);
    previous = h;
    // Radius-limited: a hit exactly when something lies within the limit.
    const double limit = 2.0;
    EXPECT_EQ(bvh.closest(p, limit).hit, ref.distance_mm <= limit);
  }
}

TEST(MeshBvhTest, ClosestPointMatchesBruteForceOnAProceduralTorus) {
  MeshBvh bvh;
  ASSERT_TRUE(bvh.add_mesh(mesh_detail::make_torus(30.0, 10.0, 48)));
  ASSERT_TRUE(bvh.commit());
  expect_bvh_matches_brute_force(bvh, glm::dvec3(-50.0), glm::dvec3(50.0), 400);
}

TEST(MeshBvhTest, ClosestPointMatchesBruteForceOnSuzanne) {
  if (!std::filesystem::exists(test::kSuzanne)) GTEST_SKIP() << "assimp-testmodels not installed";
  auto mesh = load_mesh_file(test::kSuzanne);
  ASSERT_TRUE(mesh) << mesh.error().message;
  transform_mesh(*mesh, 22.0, glm::dvec3(0.0), glm::dvec3(0.0));
  MeshBvh bvh;
  ASSERT_TRUE(bvh.add_mesh(*mesh));
  ASSERT_TRUE(bvh.commit());
  expect_bvh_matches_brute_force(bvh, mesh->bounds_min - 10.0, mesh->bounds_max + 10.0, 400);
}

TEST(MeshBvhTest, WeldedShadingNormalsOfASphereAreRadial) {
  // A UV sphere has a seam (u = 0 and u = 1 are separate vertices): after welding the vertex
  // normals are the area-weighted face normals around each vertex, within a few degrees of
  // radial on a 32-segment sphere (faces span 11.25 degrees; 0.99 = cos 8 degrees).
  MeshBvh bvh;
  ASSERT_TRUE(bvh.add_mesh(mesh_detail::make_sphere(20.0, 32)));
  ASSERT_TRUE(bvh.commit());
  for (const glm::dvec3 dir : {glm::dvec3(1, 0, 0), glm::dvec3(1, 0.001, 0.3), glm::dvec3(0.2, -1, -0.4)}) {
    const glm::dvec3 p = 30.0 * glm::normalize(dir);  // the seam is at +X
    const MeshHit h = bvh.closest(p, 1e9);
    EXPECT_GT(glm::dot(h.shaded_normal, glm::normalize(dir)), 0.99);
  }
}

TEST(MeshBvhTest, RadiusLimitedQueriesTouchOnlyTheLocalModel) {
  // Hanson & Zhang §4.2 / Table 1: a query near the proxy examines only nearby facets. A torus of
  // 48 x 24 x 2 = 2304 triangles, area 4 pi^2 R r = 11844 mm^2; a query 1 mm off the surface
  // limited to 9 mm (R = 8 + 1) covers at most a disc of ~pi 9^2 = 254 mm^2: 2 % of the area,
  // ~50 triangles. Embree visits whole leaves (up to 4 triangles each, boxes larger than the
  // disc), so allow 4x that, and require at least the triangles within the limit.
  MeshBvh bvh;
  ASSERT_TRUE(bvh.add_mesh(mesh_detail::make_torus(30.0, 10.0, 48)));
  ASSERT_TRUE(bvh.commit());
  const glm::dvec3 p{41.0, 0.0, 0.0};  // 1 mm outside the outer equator
  const MeshHit local = bvh.closest(p, 9.0);
  const MeshHit overall = bvh.closest(p, 1e9);
  ASSERT_TRUE(local.hit);
  EXPECT_NEAR(local.distance_mm, overall.distance_mm, 1e-12);
  EXPECT_GE(local.visited, 1u);
  EXPECT_LE(local.visited, 4u * 50u);
  // Continuity: starting from the hit of a query 0.1 mm away, Embree prunes with that
  // triangle's distance from the first node on: no more triangles than without the hint.
  const MeshHit next = bvh.closest(p + glm::dvec3(0.0, 0.1, 0.0), 9.0, &local);
  EXPECT_LE(next.visited, local.visited);
  EXPECT_EQ(bvh.triangle_count(), 2304u);
}

TEST(HapticSceneTest, MeshAndHeightFieldSurfacesGoThroughTheBvhWithTheirMaterial) {
  const std::string obj = test::write_sphere_obj("bvh_sphere", 20.0, 16);
  Scene sc = test::scene_with(5.0, {test::mesh_surface(obj, {100.0, 0.0, 0.0}),
                                    test::analytic(SurfaceType::kSphere, {-100.0, 0.0, 0.0})});
  sc.materials.push_back(sc.materials[0]);
  sc.materials[1].haptic.stiffness_n_per_mm = 1.25;
  sc.surfaces[0].material_index = 1;
  auto scene = HapticScene::build(sc);
  ASSERT_TRUE(scene) << scene.error().message;
  const Contact c = scene->closest({100.0, 0.0, 30.0}, 1e9);
  EXPECT_EQ(c.surface, 0);
  // 0.4 mm: the 16-segment sphere's faces sag up to r (1 - cos(11.25 deg)) = 0.38 mm inside.
  EXPECT_NEAR(c.distance_mm, 10.0, 0.4);
  EXPECT_EQ(scene->material(c.surface).stiffness_n_per_mm, 1.25);
  EXPECT_EQ(scene->closest({-100.0, 0.0, 60.0}, 1e9).surface, 1);
}

TEST(HapticSceneTest, UnloadableMeshIsAnErrorAtTheSurfacesLine) {
  Scene sc = test::scene_with(5.0, {test::mesh_surface("no_such_mesh.obj")});
  sc.surfaces[0].line = 42;
  auto scene = HapticScene::build(sc);
  ASSERT_FALSE(scene);
  EXPECT_EQ(scene.error().message.rfind("test.toml:42: ", 0), 0u) << scene.error().message;
}

}  // namespace
}  // namespace ps::world
