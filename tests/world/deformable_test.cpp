// The bendable polygons of A Virtual Universe §6 (world/deformable.h) on a tessellated sphere,
// against what the model promises: the dent takes the probe's shape and no more, the free vertices
// settle where the spring web balances (checked with an adjacency built here, independently),
// springs bring the surface back, seams stay closed, and nothing a probe does makes a vertex NaN or
// move past the bound. No GL.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <set>
#include <tuple>

#include "scene/mesh.h"
#include "scene/scene_io.h"
#include "world/deformable.h"
#include "world/deformable_surfaces.h"

namespace ps::world {
namespace {

// A position on a 1e-4 mm grid: copies of a vertex (a seam repeats its positions to rounding).
std::tuple<long long, long long, long long> key(const glm::vec3& p) {
  return {std::llround(p.x * 1e4), std::llround(p.y * 1e4), std::llround(p.z * 1e4)};
}

constexpr double kRadius = 20.0, kProbe = 6.0;

Mesh sphere_mesh(int resolution = 48) {
  Surface s;
  s.type = SurfaceType::kSphere;
  s.radius_mm = kRadius;
  s.resolution = resolution;
  auto m = build_surface_mesh(s);
  EXPECT_TRUE(m) << m.error().message;
  return m.value();
}

DeformParams params() {
  DeformParams p;
  p.enabled = true;
  p.base_n_per_mm = 0.05;
  p.neighbour_n_per_mm = 0.2;
  p.damping_n_s_per_mm = 0.004;
  p.mass_g = 1.0;
  p.max_mm = 6.0;
  return p;
}

// The probe resting on the north pole, pressed in by `depth` mm.
glm::dvec3 pressing(double depth) { return {0.0, 0.0, kRadius + kProbe - depth}; }

void run(Deformable& d, double seconds, const glm::dvec3& centre, double radius = kProbe) {
  for (int i = 0; i < static_cast<int>(std::lround(seconds * 60.0)); ++i) d.step(1.0 / 60.0, centre, radius);
}

// Pressed 2 mm in for 2 s: the pole vertex sits kContactOverlapMm inside the probe's surface,
// 2 mm - kContactOverlapMm below its base point; no vertex is deeper inside the probe (1e-9 mm:
// the constraint projects exactly); the dent fades with the angle from the pole (ring means).
TEST(DeformableTest, TheDentTakesTheProbesShape) {
  const Mesh mesh = sphere_mesh();
  Deformable d(mesh, params());
  ASSERT_LT(d.welded_count(), mesh.positions.size()) << "a UV sphere has seam and pole copies to weld";
  run(d, 2.0, pressing(2.0));
  double deepest = 0.0;
  std::map<int, std::pair<double, int>> rings;  // 5-degree rings from the pole: sum, count
  for (std::size_t i = 0; i < d.welded_count(); ++i) {
    const glm::dvec3 x = d.positions()[i], b = d.base_points()[i];
    EXPECT_GE(glm::length(x - pressing(2.0)), kProbe - kContactOverlapMm - 1e-9) << "vertex " << i << " inside the probe";
    const double u = glm::length(x - b);
    deepest = std::max(deepest, u);
    if (b.z > 0.0) {
      auto& r = rings[static_cast<int>(std::acos(std::clamp(b.z / kRadius, -1.0, 1.0)) * 180.0 / M_PI / 5.0)];
      r.first += u;
      ++r.second;
    }
  }
  EXPECT_NEAR(deepest, 2.0 - kContactOverlapMm, 1e-6);
  double last = 1e9;
  for (const auto& [ring, sum_count] : rings) {
    if (ring > 12) break;
    const double mean = sum_count.first / sum_count.second;
    EXPECT_LT(mean, last) << "ring " << ring * 5 << " deg";
    last = mean;
  }
  EXPECT_GT(rings.at(3).first / rings.at(3).second, 0.05) << "neighbours should be pulled along";
}

// At rest under the probe, every vertex the probe does not hold balances its springs:
// -k_b u_i + k_n sum_j (u_j - u_i) = 0, with the neighbours j found here from the triangles
// (welded by position). Residual below 4 k_n x 1e-4 mm (8e-4 of the press's k_b x 2 mm): the
// window leaves vertices under 1e-4 mm at rest, so a window's edge may be off by that much.
TEST(DeformableTest, FreeVerticesSettleWhereTheSpringWebBalances) {
  const Mesh mesh = sphere_mesh();
  const DeformParams p = params();
  Deformable d(mesh, p);
  run(d, 3.0, pressing(2.0));
  std::map<std::tuple<long long, long long, long long>, std::size_t> index;
  for (std::size_t i = 0; i < d.welded_count(); ++i) index[key(glm::vec3(d.base_points()[i]))] = i;
  auto welded = [&](std::uint32_t v) { return index.at(key(mesh.positions[v])); };
  std::vector<std::set<std::size_t>> nbr(d.welded_count());
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      const std::size_t a = welded(mesh.indices[t + k]), b = welded(mesh.indices[t + (k + 1) % 3]);
      if (a != b) nbr[a].insert(b), nbr[b].insert(a);
    }
  auto u = [&](std::size_t i) { return d.positions()[i] - d.base_points()[i]; };
  double worst = 0.0;
  int free_moved = 0;
  for (std::size_t i = 0; i < d.welded_count(); ++i) {
    if (glm::length(d.positions()[i] - pressing(2.0)) < kProbe - kContactOverlapMm + 1e-6) continue;  // held
    glm::dvec3 f = -p.base_n_per_mm * u(i);
    for (std::size_t j : nbr[i]) f += p.neighbour_n_per_mm * (u(j) - u(i));
    worst = std::max(worst, glm::length(f));
    if (glm::length(u(i)) > 0.01) ++free_moved;
  }
  EXPECT_GT(free_moved, 10) << "the web should carry the dent beyond the contact";
  EXPECT_LT(worst, 4.0 * p.neighbour_n_per_mm * 1e-4);
}

// Released, the springs bring every vertex back (the overdamped web's slowest mode decays as
// exp(-k_b t / c) = exp(-12.5 t): after 1.5 s the dent is below 1e-8 of its 2 mm, and every
// vertex has been put exactly at rest by the window).
TEST(DeformableTest, SpringsReturnTheSurfaceToRestWhenTheProbeLeaves) {
  Deformable d(sphere_mesh(), params());
  run(d, 1.0, pressing(2.0));
  ASSERT_GT(d.max_displacement_mm(), 1.8);
  run(d, 1.5, glm::dvec3(0.0, 0.0, 200.0));
  EXPECT_EQ(d.max_displacement_mm(), 0.0);
  d.step(0.05, pressing(1.0), kProbe);
  d.reset();
  EXPECT_EQ(d.max_displacement_mm(), 0.0);
}

// Written back into the drawn mesh, copies of one vertex (the seam, the poles) move together and
// share a normal: no crack opens and the shading stays smooth across the seam.
TEST(DeformableTest, SeamsStayClosedAndSmooth) {
  Mesh mesh = sphere_mesh();
  const Mesh rest = mesh;
  Deformable d(mesh, params());
  run(d, 0.5, glm::dvec3(kRadius + kProbe - 2.0, 0.0, 0.0));  // on the x axis: the UV seam
  d.write(mesh);
  std::map<std::tuple<long long, long long, long long>, std::size_t> first;
  int copies = 0;
  double moved = 0.0;
  for (std::size_t i = 0; i < rest.positions.size(); ++i) {
    const glm::vec3 b = rest.positions[i];
    moved = std::max(moved, static_cast<double>(glm::length(mesh.positions[i] - b)));
    const auto [it, inserted] = first.try_emplace(key(b), i);
    if (inserted) continue;
    ++copies;
    EXPECT_EQ(mesh.positions[i], mesh.positions[it->second]) << i;
    // The sphere's copies have one rest normal, so they keep one normal (no crease appears).
    EXPECT_LT(glm::length(mesh.normals[i] - mesh.normals[it->second]), 1e-6) << i;
  }
  EXPECT_GT(copies, 0);
  EXPECT_GT(moved, 1.5) << "the seam should be dented";
}

// However the probe moves (jumps across the sphere, inside it, a huge probe, NaN centres, steps
// of 0, 1 us and 0.5 s), no vertex becomes NaN and none moves farther than max_mm (exactly: the
// bound is a clamp).
TEST(DeformableTest, ViolentProbeNeverMakesNaNOrPassesTheBound) {
  DeformParams p = params();
  p.max_mm = 3.0;
  Deformable d(sphere_mesh(24), p);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pos(-40.0, 40.0), radius(0.5, 30.0);
  const double steps[] = {0.0, 1e-6, 1.0 / 60.0, 0.5};
  for (int i = 0; i < 800; ++i) {
    glm::dvec3 c(pos(rng), pos(rng), pos(rng));
    if (i % 97 == 0) c.x = std::nan("");
    if (i % 89 == 0) c.y = std::numeric_limits<double>::infinity();
    const double r = i % 50 == 0 ? std::nan("") : radius(rng);
    d.step(steps[i % 4], c, r);
    ASSERT_TRUE(d.finite()) << "step " << i;
    ASSERT_LE(d.max_displacement_mm(), p.max_mm + 1e-12) << "step " << i;
  }
}

// Stiff springs and a light mass: the substep shrinks to 0.5 / omega_max of the web (omega_max^2 =
// (k_b + 2 deg_max k_n) / m, deg_max counted here from the triangles), so the integration stays
// stable: finite, within the bound, and back at rest once released (1 % of the dent after 1 s:
// the slowest mode decays as exp(-k_b t / c) = exp(-40 t) once overdamped, and no slower here).
TEST(DeformableTest, StiffWebsShortenTheSubstepAndStayStable) {
  DeformParams p = params();
  p.neighbour_n_per_mm = 5.0;
  p.base_n_per_mm = 2.0;
  p.mass_g = 0.05;
  p.damping_n_s_per_mm = 0.05;
  Surface s;
  s.type = SurfaceType::kSphere;
  s.radius_mm = kRadius;
  s.resolution = 16;
  auto mesh = build_surface_mesh(s);
  ASSERT_TRUE(mesh);
  Deformable d(mesh.value(), p);
  std::map<std::tuple<long long, long long, long long>, std::set<std::tuple<long long, long long, long long>>> nbr;
  const auto& m = mesh.value();
  for (std::size_t t = 0; t < m.indices.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      const auto a = key(m.positions[m.indices[t + k]]), b = key(m.positions[m.indices[t + (k + 1) % 3]]);
      if (a == b) continue;
      nbr[a].insert(b);
      nbr[b].insert(a);
    }
  std::size_t deg = 0;
  for (const auto& [v, n] : nbr) deg = std::max(deg, n.size());
  EXPECT_NEAR(d.stable_substep_s(), 0.5 / std::sqrt((2.0 + 2.0 * deg * 5.0) * 1e3 / 5e-5), 1e-15);
  run(d, 0.5, pressing(1.5));
  EXPECT_TRUE(d.finite());
  const double dent = d.max_displacement_mm();
  EXPECT_GE(dent, 1.5 - kContactOverlapMm - 1e-6);
  EXPECT_LE(dent, p.max_mm);
  run(d, 1.0, glm::dvec3(0.0, 0.0, 200.0));
  EXPECT_TRUE(d.finite());
  EXPECT_LT(d.max_displacement_mm(), 0.01 * dent);
}

// The drawn probe in a deformable surface: the coupling's share k_c / (k_c + k) of the hand's
// depth, at most half the probe's radius and deform_max_mm; any other contact draws the proxy.
TEST(DeformableTest, PressedPositionIsTheCouplingsShareOfTheHandsDepth) {
  auto scene = parse_scene(
      "[probe]\nradius_mm = 6.0\n[materials.soft]\nlambda_min = 0.1\n[materials.soft.haptic]\n"
      "stiffness_n_per_mm = 0.3\n[[surfaces]]\ntype = \"sphere\"\nradius_mm = 20\nmaterial = \"soft\"\n"
      "deformable = true\ndeform_max_mm = 2.5\n[[surfaces]]\ntype = \"plane\"\nmaterial = \"soft\"\n",
      "d.toml", ".", {});
  ASSERT_TRUE(scene) << scene.error().message;
  const glm::dvec3 proxy(0.0, 0.0, 26.0);
  const glm::dvec3 pressed = pressed_position(scene.value(), 0, proxy, glm::dvec3(0.0, 0.0, 23.0), 0.5);
  EXPECT_NEAR(pressed.z, 26.0 - 3.0 * 0.5 / 0.8, 1e-12);
  EXPECT_EQ(pressed.x, 0.0);
  // 10 mm in: 6.25 mm by the share, limited to min(2.5, 6 / 2).
  EXPECT_NEAR(pressed_position(scene.value(), 0, proxy, glm::dvec3(0.0, 0.0, 16.0), 0.5).z, 23.5, 1e-12);
  EXPECT_EQ(pressed_position(scene.value(), 1, proxy, glm::dvec3(0.0, 0.0, 23.0), 0.5), proxy);
  EXPECT_EQ(pressed_position(scene.value(), -1, proxy, glm::dvec3(0.0, 0.0, 23.0), 0.5), proxy);
  EXPECT_EQ(pressed_position(scene.value(), 0, proxy, glm::dvec3(std::nan(""), 0.0, 0.0), 0.5), proxy);
}

// Subdivision: every edge ends at or under max_edge_mm (three levels suffice here), each triangle
// became four of a quarter of its area (total area kept to float precision), shared edges share
// their midpoint (no T-junctions: welded, each edge is in exactly two triangles of the closed
// sphere), and a press moves only a window of the vertices, not the whole mesh. (Three levels
// of a 16-segment sphere of radius 20 mm: the diagonals end near 1.35 mm.)
TEST(DeformableTest, SubdividedMeshesAreClosedAndPressesStayLocal) {
  const Mesh coarse = sphere_mesh(16);
  const Mesh fine = subdivide(coarse, 1.5);
  auto area = [](const Mesh& m) {
    double a = 0.0;
    for (std::size_t t = 0; t < m.indices.size(); t += 3)
      a += 0.5 * glm::length(glm::cross(glm::dvec3(m.positions[m.indices[t + 1]] - m.positions[m.indices[t]]),
                                         glm::dvec3(m.positions[m.indices[t + 2]] - m.positions[m.indices[t]])));
    return a;
  };
  EXPECT_NEAR(area(fine), area(coarse), 1e-5 * area(coarse));
  std::map<std::tuple<long long, long long, long long>, std::uint32_t> weld;
  auto id = [&](std::uint32_t v) {
    return weld.try_emplace(key(fine.positions[v]), static_cast<std::uint32_t>(weld.size())).first->second;
  };
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  double longest = 0.0;
  for (std::size_t t = 0; t < fine.indices.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = fine.indices[t + k], b = fine.indices[t + (k + 1) % 3];
      longest = std::max(longest, static_cast<double>(glm::length(fine.positions[a] - fine.positions[b])));
      const std::uint32_t wa = id(a), wb = id(b);
      if (wa != wb) ++edges[std::minmax(wa, wb)];
    }
  EXPECT_LE(longest, 1.5);
  EXPECT_EQ(fine.indices.size(), coarse.indices.size() * 64) << "three levels of four";
  for (const auto& [e, n] : edges) ASSERT_EQ(n, 2) << "edge " << e.first << "-" << e.second;
  Deformable d(fine, params());
  run(d, 0.5, pressing(1.0));
  EXPECT_GT(d.active_count(), 0u);
  // With k_b / k_n = 1/4 a dent decays by ~0.6 per ring of neighbours, so a 1 mm press reaches
  // the 1e-4 mm rest threshold ~18 rings out: a cap of the sphere, not all of it.
  EXPECT_LT(d.active_count(), d.welded_count() / 2) << "the window should hold the press's neighbourhood only";
}

// A scene of one deformable sphere (the one above, surface 1 behind a plain plane) with the
// scene's probe `depth` mm into its north pole: what world::settled_deformables settles.
Scene pressed_sphere_scene(double depth) {
  Scene scene;
  Surface plane;
  plane.type = SurfaceType::kPlane;
  plane.center = {0.0, 0.0, -40.0};
  Surface sphere;
  sphere.type = SurfaceType::kSphere;
  sphere.radius_mm = kRadius;
  sphere.resolution = 24;
  sphere.deform = params();
  scene.surfaces = {plane, sphere};
  scene.probe.shape = ProbeShape::kSphere;
  scene.probe.radius_mm = kProbe;
  scene.probe.position = pressing(depth);
  return scene;
}

// The deformable surfaces' stepping is the world's (the session drives it; the renderer only
// uploads by version): settled_deformables holds each deformable surface of a scene under its
// own index, settles it for 1 s (ten 0.1 s steps, each of which moves a pressed surface: version
// 10) exactly as stepping a DeformableSurfaces built by hand does, and leaves a surface the
// probe is far from at its rest mesh (version 0). advance() steps only once the clock is set.
TEST(DeformableSurfacesTest, TheWorldSettlesAndStepsAndCountsEachStepThatMovedASurface) {
  const Scene scene = pressed_sphere_scene(2.0);
  auto settled = settled_deformables(scene);
  ASSERT_TRUE(settled) << settled.error().message;
  ASSERT_TRUE(settled.value());
  DeformableSurfaces& w = *settled.value();
  ASSERT_EQ(w.drawn().size(), 1u);
  EXPECT_EQ(w.drawn()[0].surface, 1);
  EXPECT_EQ(w.drawn()[0].version, 10u);
  EXPECT_EQ(w.mesh(0), nullptr);
  ASSERT_NE(w.mesh(1), nullptr);

  // The same settling by hand, from the sphere's own drawn mesh.
  DeformableSurfaces by_hand;
  auto rest = build_drawn_surface_mesh(scene.surfaces[1]);
  ASSERT_TRUE(rest) << rest.error().message;
  by_hand.add(1, rest.value(), scene.surfaces[1].deform);
  for (int i = 0; i < 10; ++i) by_hand.step(0.1, scene.probe);
  EXPECT_EQ(w.mesh(1)->positions, by_hand.mesh(1)->positions);
  EXPECT_EQ(w.mesh(1)->normals, by_hand.mesh(1)->normals);
  EXPECT_GT(w.stats().max_displacement_mm, 1.0);
  // The dented mesh keeps the rest mesh's bounds (the renderer culls with them, unbuilt again).
  EXPECT_EQ(w.mesh(1)->bounds_min, rest.value().bounds_min);
  EXPECT_EQ(w.mesh(1)->bounds_max, rest.value().bounds_max);

  // The session's clock: the first advance only sets it, the next one steps and moves the
  // pressed surface once more; an advance to the same time does nothing.
  const std::uint64_t before = w.drawn()[0].version;
  w.advance(5.0, scene.probe);
  EXPECT_EQ(w.drawn()[0].version, before);
  w.advance(5.1, scene.probe);
  EXPECT_EQ(w.drawn()[0].version, before + 1);
  w.advance(5.1, scene.probe);
  EXPECT_EQ(w.drawn()[0].version, before + 1);

  // Far from the probe: settled, never moved, the subdivided rest mesh.
  const Scene away = pressed_sphere_scene(-30.0);
  auto rest_world = settled_deformables(away);
  ASSERT_TRUE(rest_world && rest_world.value());
  EXPECT_EQ(rest_world.value()->drawn()[0].version, 0u);
  EXPECT_EQ(rest_world.value()->mesh(1)->positions, subdivide(rest.value(), params().max_edge_mm).positions);

  // No deformable surface: no world at all.
  Scene plain = scene;
  plain.surfaces[1].deform.enabled = false;
  auto none = settled_deformables(plain);
  ASSERT_TRUE(none);
  EXPECT_EQ(none.value(), nullptr);
}

}  // namespace
}  // namespace ps::world
