// The 4D maths and the shipped surfaces against closed forms: rotations are orthonormal,
// projection round-trips, the flat torus lies on the 3-sphere of radius sqrt 2 with w in its
// known range, the Roman surface's image crosses itself along its three double lines, and the
// scenes under scenes/fourd load at Hanson & Zhang's polygon counts. No GL.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fourd/fourd_mesh.h"
#include "fourd/rotation4.h"
#include "fourd/surfaces.h"
#include "scene/mesh.h"
#include "scene/scene_io.h"

namespace ps::fourd {
namespace {

// R^T R = I and det R = +1 for each plane and for compositions of random angles (1e-12:
// double rounding of a few products of sines and cosines).
TEST(FourdRotationTest, PlaneRotationsAreOrthonormal) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(-720.0, 720.0);
  for (int trial = 0; trial < 50; ++trial) {
    std::array<double, 6> deg{};
    for (double& d : deg) d = angle(rng);
    const glm::dmat4 r = rotation_from_deg(deg);
    const glm::dmat4 rtr = glm::transpose(r) * r;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) EXPECT_NEAR(rtr[i][j], i == j ? 1.0 : 0.0, 1e-12) << i << "," << j;
    EXPECT_NEAR(glm::determinant(r), 1.0, 1e-12);
  }
  // A quarter turn in the xw plane takes x to w (e_a turns toward e_b) and leaves y, z alone.
  const glm::dvec4 x = plane_rotation(0, 3, M_PI / 2) * glm::dvec4(1, 0, 0, 0);
  EXPECT_NEAR(x.w, 1.0, 1e-15);
  EXPECT_NEAR(x.x, 0.0, 1e-15);
  const glm::dvec4 y = plane_rotation(0, 3, M_PI / 2) * glm::dvec4(0, 1, 0, 0);
  EXPECT_EQ(y, glm::dvec4(0, 1, 0, 0));
}

// project then unproject gives the point back (1e-12 relative: one division and one product).
TEST(FourdProjectionTest, ProjectUnprojectRoundTrips) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> c(-1.5, 1.5);
  for (Projection4 kind : {Projection4::kPerspective, Projection4::kOrthographic}) {
    for (int trial = 0; trial < 100; ++trial) {
      const glm::dvec4 p(c(rng), c(rng), c(rng), c(rng));
      const Projected q = project(p, kind, 4.0);
      EXPECT_EQ(q.w, p.w);
      const glm::dvec4 back = unproject(q.p3, q.w, kind, 4.0);
      for (int i = 0; i < 4; ++i) EXPECT_NEAR(back[i], p[i], 1e-12) << i;
    }
  }
  // Perspective: a point at w = E/2 is drawn twice as far from the axis; w = 0 is unchanged.
  EXPECT_NEAR(project({1, 0, 0, 2}, Projection4::kPerspective, 4.0).p3.x, 2.0, 1e-15);
  EXPECT_EQ(project({1, 2, 3, 0}, Projection4::kPerspective, 4.0).p3, glm::dvec3(1, 2, 3));
}

// Every vertex of the rotated flat torus has |p| = sqrt 2 (rotations keep it on the 3-sphere),
// and w = r4 . p has the range +-(|(r4x, r4y)| + |(r4z, r4w)|), r4 the rotation's last row:
// the mesh's extreme w is within the sampling error of the 30 x 30 grid (the cosine's dip
// over half a cell, 1 - cos(pi/30) < 6e-3 of the amplitude) of the analytic one.
TEST(FourdSurfaceTest, FlatTorusLiesOnTheThreeSphereWithKnownDepthRange) {
  Spec spec;
  spec.kind = SurfaceKind::kFlatTorus;
  spec.rotation_deg = {10.0, 20.0, 30.0, 40.0, 50.0, 60.0};
  spec.eye_distance = 4.0;
  auto mesh = build_fourd_mesh(spec);
  ASSERT_TRUE(mesh) << mesh.error().message;
  EXPECT_EQ(mesh->polygons(), 900);
  for (const Vertex4& v : mesh->vertices) EXPECT_NEAR(glm::length(v.p4), std::sqrt(2.0), 1e-12);
  const glm::dmat4 r = rotation_from_deg(spec.rotation_deg);
  const glm::dvec4 row(r[0][3], r[1][3], r[2][3], r[3][3]);
  const double amplitude = std::hypot(row.x, row.y) + std::hypot(row.z, row.w);
  EXPECT_LE(mesh->w_max, amplitude + 1e-12);
  EXPECT_GE(mesh->w_min, -amplitude - 1e-12);
  EXPECT_GT(mesh->w_max, amplitude * (1.0 - 2.0 * (1.0 - std::cos(M_PI / 30.0))));
  EXPECT_LT(mesh->w_min, -amplitude * (1.0 - 2.0 * (1.0 - std::cos(M_PI / 30.0))));
  // A closed surface: every triangle has three neighbours across the seams.
  for (const glm::ivec3& n : mesh->neighbours) EXPECT_TRUE(n.x >= 0 && n.y >= 0 && n.z >= 0);
}

// Sheets of the mesh's 3D image passing within `tol` of p: the w there of each facet near p,
// grouped into values farther apart than `gap`.
std::vector<double> sheets_at(const FourdMesh& m, const glm::dvec3& p, double tol, double gap) {
  std::vector<double> ws;
  for (const glm::uvec3& t : m.triangles) {
    const glm::dvec3 a = m.vertices[t.x].p3, b = m.vertices[t.y].p3, c = m.vertices[t.z].p3;
    // Closest point by projecting onto the plane and testing barycentrics (inside only: the
    // neighbours cover the edges).
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double area2 = glm::dot(n, n);
    if (area2 < 1e-30) continue;
    const double dist = glm::dot(p - a, n) / std::sqrt(area2);
    if (std::abs(dist) > tol) continue;
    const glm::dvec3 q = p - dist * n / std::sqrt(area2);
    const double u = glm::dot(glm::cross(c - b, q - b), n) / area2, v = glm::dot(glm::cross(a - c, q - c), n) / area2;
    const double w3 = 1.0 - u - v;
    if (u < -1e-9 || v < -1e-9 || w3 < -1e-9) continue;
    const double w = u * m.vertices[t.x].w + v * m.vertices[t.y].w + w3 * m.vertices[t.z].w;
    bool known = false;
    for (double s : ws) known = known || std::abs(s - w) < gap;
    if (!known) ws.push_back(w);
  }
  std::sort(ws.begin(), ws.end());
  return ws;
}

// The orthographic image of (2yz, 2xz, 2xy, y^2 - z^2) is the Roman surface 2(yz, xz, xy),
// which crosses itself along the three coordinate axes (|t| < 1): on the first axis the
// points (0, y, z) and (0, z, y) of the sphere meet, at w = y^2 - z^2 and z^2 - y^2; on the
// second (x, 0, z) and (z, 0, x) at w = -z^2 and -x^2; on the third (x, y, 0) and (y, x, 0)
// at w = y^2 and x^2. The mesh has exactly two sheets there with those w (0.02: the 40 x 40
// grid's linear interpolation of a quadratic over cells ~0.04 wide), and one sheet at a point
// of the surface off the axes.
TEST(FourdSurfaceTest, RomanSurfaceCrossesItselfAlongItsThreeDoubleLines) {
  Spec spec;
  spec.kind = SurfaceKind::kRoman;
  spec.projection = Projection4::kOrthographic;
  auto mesh = build_fourd_mesh(spec);
  ASSERT_TRUE(mesh) << mesh.error().message;
  EXPECT_EQ(mesh->polygons(), 1600);
  for (const glm::ivec3& n : mesh->neighbours) EXPECT_TRUE(n.x >= 0 && n.y >= 0 && n.z >= 0);
  for (double angle : {0.35, 0.6, 1.1}) {  // sphere points at this angle in the coordinate plane
    const double a = std::cos(angle), b = std::sin(angle);
    const double t = 2.0 * a * b;  // where on the axis both preimages land
    for (int axis = 0; axis < 3; ++axis) {
      glm::dvec3 p(0.0);
      p[axis] = t;
      // The analytic w of the two preimages: (a, b) and (b, a) in the axis's coordinate plane.
      std::vector<double> want;
      if (axis == 0) want = {a * a - b * b, b * b - a * a};
      if (axis == 1) want = {-b * b, -a * a};
      if (axis == 2) want = {b * b, a * a};
      std::sort(want.begin(), want.end());
      const std::vector<double> got = sheets_at(mesh.value(), p, 0.01, 0.1);
      ASSERT_EQ(got.size(), 2u) << "axis " << axis << " t " << t;
      EXPECT_NEAR(got[0], want[0], 0.02) << "axis " << axis << " t " << t;
      EXPECT_NEAR(got[1], want[1], 0.02) << "axis " << axis << " t " << t;
    }
  }
  // Off the axes: the image of the sphere point (0.48, 0.6, 0.64) has one sheet only.
  const glm::dvec3 s = glm::normalize(glm::dvec3(0.48, 0.6, 0.64));
  const glm::dvec3 off(2 * s.y * s.z, 2 * s.x * s.z, 2 * s.x * s.y);
  EXPECT_EQ(sheets_at(mesh.value(), off, 0.01, 0.1).size(), 1u);
}

// The spun surfaces are closed (every facet has three neighbours: the arc's ends on the
// spinning plane close the sphere); their arc's ends lie on c = 0 and the rest above it; the
// knotted part's ends (the poles) lie on the twist axis l; and, twisted, whatever the knotted
// part sweeps about l stays above the plane and clear of the fixed drops to it (which lie
// beyond its ends along a): the twist-spun surface is embedded.
TEST(FourdSurfaceTest, SpunTrefoilsAreClosedSpheres) {
  for (bool twisted : {false, true}) {
    const KnottedArc arc = KnottedArc::make(twisted);
    EXPECT_EQ(arc.points.front().z, 0.0);
    EXPECT_EQ(arc.points.back().z, 0.0);
    for (std::size_t i = 1; i + 1 < arc.points.size(); ++i) ASSERT_GT(arc.points[i].z, 0.0) << i;
    for (double pole : {arc.twist_begin, arc.twist_end}) {
      EXPECT_NEAR(arc.at(pole).y, 0.0, 1e-9);
      EXPECT_NEAR(arc.at(pole).z, arc.axis_c, 1e-9);
    }
    if (!twisted) continue;
    double a_lo = 1e9, a_hi = -1e9;
    for (std::size_t i = 0; i < arc.points.size(); ++i) {
      if (arc.s[i] <= arc.twist_begin || arc.s[i] >= arc.twist_end) continue;
      const glm::dvec3 q = arc.points[i];
      EXPECT_LT(std::hypot(q.y, q.z - arc.axis_c), arc.axis_c) << i;  // its circle about l stays above c = 0
      a_lo = std::min(a_lo, q.x);
      a_hi = std::max(a_hi, q.x);
    }
    for (std::size_t i = 0; i < arc.points.size(); ++i) {
      if (arc.s[i] < arc.twist_begin || arc.s[i] > arc.twist_end) {
        EXPECT_TRUE(arc.points[i].x < a_lo || arc.points[i].x > a_hi || std::abs(arc.points[i].z - arc.axis_c) < 1e-12)
            << i;
      }
    }
  }
  for (SurfaceKind kind : {SurfaceKind::kSpunTrefoil, SurfaceKind::kTwistSpunTrefoil}) {
    Spec spec;
    spec.kind = kind;
    auto mesh = build_fourd_mesh(spec);
    ASSERT_TRUE(mesh) << mesh.error().message;
    EXPECT_EQ(mesh->polygons(), 2800);
    int open = 0;
    for (const glm::ivec3& n : mesh->neighbours) open += (n.x < 0) + (n.y < 0) + (n.z < 0);
    EXPECT_EQ(open, 0) << surface_name(kind);
  }
}

// A perspective eye inside the surface is a scene error that says what to change.
TEST(FourdSurfaceTest, EyeInsideTheSurfaceIsAnError) {
  Spec spec;
  spec.eye_distance = 1.0;  // the flat torus reaches w = 1
  auto mesh = build_fourd_mesh(spec);
  ASSERT_FALSE(mesh);
  EXPECT_NE(mesh.error().message.find("fourd_eye_distance"), std::string::npos) << mesh.error().message;
}

// The shipped scenes load, and their meshes have Hanson & Zhang's polygon counts (two triangles a
// polygon, minus the poles' degenerate ones) and a colour per vertex.
TEST(FourdSceneTest, ShippedScenesLoadAtThePapersPolygonCounts) {
  const std::pair<const char*, int> scenes[] = {
      {"flat_torus", 900}, {"spun_trefoil", 2800}, {"roman", 1600}, {"twist_spun_trefoil", 2800}};
  for (const auto& [name, polygons] : scenes) {
    auto scene = load_scene(std::string(PS_SOURCE_DIR) + "/scenes/fourd/" + name + ".toml");
    ASSERT_TRUE(scene) << scene.error().message;
    ASSERT_EQ(scene->surfaces[0].type, SurfaceType::kFourd);
    auto mesh = build_surface_mesh(scene->surfaces[0]);
    ASSERT_TRUE(mesh) << mesh.error().message;
    EXPECT_LE(mesh->indices.size() / 3, static_cast<std::size_t>(2 * polygons)) << name;
    EXPECT_GE(mesh->indices.size() / 3, static_cast<std::size_t>(2 * polygons * 0.95)) << name;
    EXPECT_EQ(mesh->colors.size(), mesh->positions.size()) << name;
  }
}

// fourd_* keys on another surface type and a fourd surface without `fourd` are errors naming
// the line and the fix.
TEST(FourdSceneTest, BadKeysAreErrors) {
  const std::string head = "[materials.m]\n[[surfaces]]\nmaterial = \"m\"\n";
  auto a = parse_scene(head + "type = \"plane\"\nfourd_twists = 3\n", "a.toml", ".");
  ASSERT_FALSE(a);
  EXPECT_NE(a.error().message.find("applies only to type = \"fourd\""), std::string::npos) << a.error().message;
  auto b = parse_scene(head + "type = \"fourd\"\n", "b.toml", ".");
  ASSERT_FALSE(b);
  EXPECT_NE(b.error().message.find("'fourd' is required"), std::string::npos) << b.error().message;
  auto c = parse_scene(head + "type = \"fourd\"\nfourd = \"klein\"\n", "c.toml", ".");
  ASSERT_FALSE(c);
  EXPECT_NE(c.error().message.find("c.toml:"), std::string::npos) << c.error().message;
  // The eye inside the flat torus (it reaches w = 1): the file and the surface's line, the fix.
  auto d = parse_scene(head + "type = \"fourd\"\nfourd = \"flat_torus\"\nfourd_eye_distance = 1.0\n", "d.toml", ".");
  ASSERT_FALSE(d);
  EXPECT_NE(d.error().message.find("d.toml:6: 'fourd_eye_distance'"), std::string::npos) << d.error().message;
  EXPECT_NE(d.error().message.find("make fourd_eye_distance larger than"), std::string::npos) << d.error().message;
  // The rolling manifold's keys: a negative time constant, a tether on a plane.
  auto e = parse_scene(head + "type = \"fourd\"\nfourd = \"roman\"\nfourd_roll = true\nfourd_roll_turn_s = -1\n", "e.toml", ".");
  ASSERT_FALSE(e);
  EXPECT_NE(e.error().message.find("e.toml:7: 'fourd_roll_turn_s'"), std::string::npos) << e.error().message;
  auto f = parse_scene(head + "type = \"plane\"\nfourd_roll_tether_n_per_mm4 = 1e-4\n", "f.toml", ".");
  ASSERT_FALSE(f);
  EXPECT_NE(f.error().message.find("applies only to type = \"fourd\""), std::string::npos) << f.error().message;
  auto g = parse_scene(head + "type = \"fourd\"\nfourd = \"roman\"\nfourd_roll = true\nfourd_roll_centre_s = 0\n", "g.toml", ".");
  ASSERT_TRUE(g) << g.error().message;
  EXPECT_TRUE(g.value().surfaces[0].fourd.roll.on);
  EXPECT_EQ(g.value().surfaces[0].fourd.roll.centre_s, 0.0);
}

}  // namespace
}  // namespace ps::fourd
