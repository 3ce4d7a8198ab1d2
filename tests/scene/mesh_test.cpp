// Procedural and file meshes: analytic checks (area, radius, outward normals, winding).
#include <fstream>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "scene/mesh.h"

namespace ps {
namespace {

constexpr const char* kSuzanne = "/usr/share/assimp/models/BLEND/Suzanne_248.blend";

glm::dvec3 pos(const Mesh& m, std::uint32_t i) { return glm::dvec3(m.positions[i]); }

// Geometric normal of each triangle must agree with its vertex normals (CCW from outside).
void expect_consistent_winding(const Mesh& mesh) {
  ASSERT_EQ(mesh.indices.size() % 3, 0u);
  int bad = 0;
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
    const auto a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    const glm::dvec3 n = glm::cross(pos(mesh, b) - pos(mesh, a), pos(mesh, c) - pos(mesh, a));
    const glm::dvec3 vn = glm::dvec3(mesh.normals[a] + mesh.normals[b] + mesh.normals[c]);
    if (glm::dot(n, vn) <= 0.0) ++bad;
  }
  EXPECT_EQ(bad, 0) << "triangles wound against their normals";
}

double total_area(const Mesh& mesh) {
  double area = 0.0;
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
    const auto a = pos(mesh, mesh.indices[t]);
    area += 0.5 * glm::length(glm::cross(pos(mesh, mesh.indices[t + 1]) - a,
                                         pos(mesh, mesh.indices[t + 2]) - a));
  }
  return area;
}

TEST(MeshTest, PlaneNormalsUpAndAreaIsSize) {
  Surface s;
  s.type = SurfaceType::kPlane;
  s.size_mm = {200.0, 120.0};
  s.resolution = 7;
  Result<Mesh> mesh = build_surface_mesh(s);
  ASSERT_TRUE(mesh) << mesh.error().message;
  for (const glm::vec3& n : mesh->normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
  EXPECT_NEAR(total_area(*mesh), 200.0 * 120.0, 1e-6 * 200.0 * 120.0);
  EXPECT_EQ(mesh->indices.size(), 7u * 7u * 6u);
  expect_consistent_winding(*mesh);
  EXPECT_DOUBLE_EQ(mesh->bounds_min.x, -100.0);
  EXPECT_DOUBLE_EQ(mesh->bounds_max.y, 60.0);
}

TEST(MeshTest, PlaneRotatedAndMoved) {
  Surface s;
  s.size_mm = {10.0, 10.0};
  s.rotation_deg = {90.0, 0.0, 0.0};  // +Z normal turns to -Y
  s.center = {1.0, 2.0, 3.0};
  Result<Mesh> mesh = build_surface_mesh(s);
  ASSERT_TRUE(mesh);
  EXPECT_NEAR(mesh->normals[0].y, -1.0f, 1e-6f);
  EXPECT_NEAR(mesh->bounds_min.y, 2.0, 1e-6);
  EXPECT_NEAR(mesh->bounds_max.z, 8.0, 1e-5);
}

// A closed, outward-wound box: its flat normals point away from the centre along one axis,
// its area is 2(xy + yz + zx) and the divergence theorem gives its volume xyz.
TEST(MeshTest, BoxHasFlatOutwardFacesAreaAndVolume) {
  Surface s;
  s.type = SurfaceType::kBox;
  s.box_size_mm = {10.0, 20.0, 30.0};
  s.center = {1.0, 2.0, 3.0};
  Result<Mesh> mesh = build_surface_mesh(s);
  ASSERT_TRUE(mesh) << mesh.error().message;
  EXPECT_EQ(mesh->indices.size(), 36u);  // 6 faces x 2 triangles
  expect_consistent_winding(*mesh);
  for (std::size_t i = 0; i < mesh->positions.size(); ++i) {
    const glm::dvec3 n(mesh->normals[i]);
    const glm::dvec3 from_centre = pos(*mesh, static_cast<std::uint32_t>(i)) - s.center;
    EXPECT_EQ(glm::length(n), 1.0);
    EXPECT_EQ(std::abs(n.x) + std::abs(n.y) + std::abs(n.z), 1.0) << "axis-aligned, flat";
    EXPECT_DOUBLE_EQ(glm::dot(n, from_centre), glm::dot(glm::abs(n), 0.5 * s.box_size_mm))
        << "vertex " << i << " lies on its face's plane";
  }
  EXPECT_DOUBLE_EQ(total_area(*mesh), 2.0 * (10.0 * 20.0 + 20.0 * 30.0 + 30.0 * 10.0));
  double volume = 0.0;  // sum over triangles of a . (b x c) / 6
  for (std::size_t t = 0; t < mesh->indices.size(); t += 3) {
    volume += glm::dot(pos(*mesh, mesh->indices[t]),
                       glm::cross(pos(*mesh, mesh->indices[t + 1]),
                                  pos(*mesh, mesh->indices[t + 2]))) / 6.0;
  }
  // Float positions (mesh storage) of coordinates up to 18 mm: ~1e-6 relative per product.
  EXPECT_NEAR(volume, 10.0 * 20.0 * 30.0, 1e-4 * 6000.0);
  EXPECT_DOUBLE_EQ(mesh->bounds_min.x, -4.0);
  EXPECT_DOUBLE_EQ(mesh->bounds_max.z, 18.0);
}

TEST(MeshTest, SphereVerticesOnRadiusNormalsOutward) {
  Surface s;
  s.type = SurfaceType::kSphere;
  s.radius_mm = 37.0;
  s.resolution = 48;
  Result<Mesh> mesh = build_surface_mesh(s);
  ASSERT_TRUE(mesh);
  double max_rel = 0.0;
  for (std::size_t i = 0; i < mesh->positions.size(); ++i) {
    const glm::dvec3 p = pos(*mesh, static_cast<std::uint32_t>(i));
    max_rel = std::max(max_rel, std::abs(glm::length(p) - 37.0) / 37.0);
    EXPECT_GT(glm::dot(p, glm::dvec3(mesh->normals[i])), 0.99 * 37.0);
  }
  EXPECT_LT(max_rel, 1e-5);
  expect_consistent_winding(*mesh);
  // Tessellated area approaches 4 pi r^2 from below.
  const double sphere_area = 4.0 * M_PI * 37.0 * 37.0;
  EXPECT_GT(total_area(*mesh), 0.99 * sphere_area);
  EXPECT_LT(total_area(*mesh), sphere_area);
}

TEST(MeshTest, TorusPointsAtTubeRadius) {
  Surface s;
  s.type = SurfaceType::kTorus;
  s.radius_mm = 40.0;
  s.minor_radius_mm = 10.0;
  s.resolution = 32;
  Result<Mesh> mesh = build_surface_mesh(s);
  ASSERT_TRUE(mesh);
  for (std::size_t i = 0; i < mesh->positions.size(); ++i) {
    const glm::dvec3 p = pos(*mesh, static_cast<std::uint32_t>(i));
    const glm::dvec3 ring = 40.0 * glm::normalize(glm::dvec3(p.x, p.y, 0.0));
    EXPECT_NEAR(glm::length(p - ring), 10.0, 1e-4);
    EXPECT_GT(glm::dot(p - ring, glm::dvec3(mesh->normals[i])), 9.9);  // outward from the tube
  }
  expect_consistent_winding(*mesh);
  EXPECT_NEAR(mesh->bounds_max.x, 50.0, 1e-4);
  EXPECT_NEAR(mesh->bounds_max.z, 10.0, 0.1);
}

TEST(MeshTest, HeightFieldWithinHeightRange) {
  Surface s;
  s.type = SurfaceType::kHeightField;
  s.heightmap = std::string(PS_SOURCE_DIR) + "/textures/heightfield.png";
  s.size_mm = {100.0, 80.0};
  s.height_mm = 6.0;
  s.resolution = 32;
  Result<Mesh> mesh = build_surface_mesh(s);
  ASSERT_TRUE(mesh) << mesh.error().message;
  EXPECT_GE(mesh->bounds_min.z, 0.0);
  EXPECT_LE(mesh->bounds_max.z, 6.0 + 1e-5);
  EXPECT_GT(mesh->bounds_max.z - mesh->bounds_min.z, 1.0) << "the image should not be flat";
  EXPECT_NEAR(mesh->bounds_max.x - mesh->bounds_min.x, 100.0, 1e-4);
  for (const glm::vec3& n : mesh->normals) EXPECT_GT(n.z, 0.0f);
  expect_consistent_winding(*mesh);
}

TEST(MeshTest, MissingHeightMapNamesTheFile) {
  Surface s;
  s.type = SurfaceType::kHeightField;
  s.heightmap = "/nonexistent/bumps.png";
  Result<Mesh> mesh = build_surface_mesh(s);
  ASSERT_FALSE(mesh);
  EXPECT_NE(mesh.error().message.find("/nonexistent/bumps.png"), std::string::npos);
}

TEST(MeshTest, SuzanneLoadsThroughAssimp) {
  if (!std::filesystem::exists(kSuzanne)) GTEST_SKIP() << "needs Debian's assimp-testmodels";
  Result<Mesh> mesh = load_mesh_file(kSuzanne);
  ASSERT_TRUE(mesh) << mesh.error().message;
  EXPECT_GT(mesh->indices.size() / 3, 400u);
  const glm::dvec3 extent = mesh->bounds_max - mesh->bounds_min;
  EXPECT_GT(extent.x, 1.0);
  EXPECT_GT(extent.y, 1.0);
  EXPECT_GT(extent.z, 1.0);
  EXPECT_EQ(mesh->normals.size(), mesh->positions.size());
}

TEST(MeshTest, SuzanneScaledBySurface) {
  if (!std::filesystem::exists(kSuzanne)) GTEST_SKIP() << "needs Debian's assimp-testmodels";
  Surface s;
  s.type = SurfaceType::kMesh;
  s.mesh_file = kSuzanne;
  s.scale = 10.0;
  s.center = {0.0, 0.0, 100.0};
  Result<Mesh> raw = load_mesh_file(kSuzanne);
  Result<Mesh> mesh = build_surface_mesh(s);
  ASSERT_TRUE(mesh && raw);
  EXPECT_NEAR(mesh->bounds_max.x - mesh->bounds_min.x,
              10.0 * (raw->bounds_max.x - raw->bounds_min.x), 1e-3);
}

TEST(MeshTest, MissingMeshFileNamesTheFile) {
  Result<Mesh> mesh = load_mesh_file("/nonexistent/dir/probe.obj");
  ASSERT_FALSE(mesh);
  EXPECT_EQ(mesh.error().message.rfind("/nonexistent/dir/probe.obj: cannot load mesh: ", 0), 0u)
      << mesh.error().message;
}

TEST(MeshTest, HugeDeclaredCountIsRefusedBeforeAssimpAllocates) {
  // Found by fuzz_mesh: assimp allocated 8 GiB for the face count an OFF header declared.
  const auto path = std::filesystem::temp_directory_path() / "ps_mesh_test_huge.off";
  std::ofstream(path) << "OFF\n3 1999999999999 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  Result<Mesh> mesh = load_mesh_file(path.string());
  ASSERT_FALSE(mesh);
  EXPECT_NE(mesh.error().message.find("header declares more than"), std::string::npos)
      << mesh.error().message;
  std::filesystem::remove(path);
}

TEST(MeshTest, HugeCountFollowedByJunkIsRefused) {
  // Found by fuzz_mesh: assimp reads the leading digits of "19999999999<junk>" as the face count
  // and allocated 45 GB; the same for a PLY element count.
  const auto off = std::filesystem::temp_directory_path() / "ps_mesh_test_junk.off";
  std::ofstream(off) << "OFF\n3 19999999999\xbc\xbc" "99 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const auto ply = std::filesystem::temp_directory_path() / "ps_mesh_test_junk.ply";
  std::ofstream(ply) << "ply\nformat ascii 1.0\nelement vertex 99999999999\nproperty float x\n"
                        "end_header\n";
  for (const auto& path : {off, ply}) {
    Result<Mesh> mesh = load_mesh_file(path.string());
    ASSERT_FALSE(mesh) << path;
    EXPECT_NE(mesh.error().message.find("header declares more than"), std::string::npos)
        << mesh.error().message;
    std::filesystem::remove(path);
  }
}

TEST(MeshTest, PlyFaceListCutShortIsAnErrorNotAnAssimpAssert) {
  // Found by fuzz_mesh: 2 faces declared, 1 given, a misspelt property: assimp's PLY reader made
  // a mesh whose flags contradict its faces and its Triangulate step's ai_assert aborted.
  const auto path = std::filesystem::temp_directory_path() / "ps_mesh_test_short.ply";
  std::ofstream(path) << "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                         "propepty float y\nproperty float z\nelement face 2\n"
                         "property list uchar int vertex_indices\nend_header\n"
                         "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  Result<Mesh> mesh = load_mesh_file(path.string());
  ASSERT_FALSE(mesh);
  EXPECT_EQ(mesh.error().message,
            path.string() + ":5: cannot load mesh: PLY header line not understood (expected "
                            "element, property, comment or end_header)");
  std::filesystem::remove(path);
}

TEST(MeshTest, PlyWithoutEndHeaderIsRefusedNotHung) {
  // Found by fuzz_mesh: assimp 5.2's PLY reader loops forever on such headers (no end_header at
  // all; end_header at the end of a property line). The header grammar is checked first.
  const auto path = std::filesystem::temp_directory_path() / "ps_mesh_test_noend.ply";
  std::ofstream(path) << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n";
  Result<Mesh> mesh = load_mesh_file(path.string());
  ASSERT_FALSE(mesh);
  EXPECT_NE(mesh.error().message.find("no end_header"), std::string::npos) << mesh.error().message;
  std::ofstream(path) << "ply\nformat ascii 1.0\nelement vertex 1\n"
                         "property list uchar int vertex_in 0 0 end_header\n0 0 0\n";
  mesh = load_mesh_file(path.string());
  ASSERT_FALSE(mesh);
  EXPECT_EQ(mesh.error().message,
            path.string() + ":4: cannot load mesh: PLY header 'property TYPE NAME' or "
                            "'property list TYPE TYPE NAME' expected");
  std::filesystem::remove(path);
}

TEST(MeshTest, UnsupportedFormatIsRefusedBeforeAssimpReadsIt) {
  // Fuzzing found a heap overflow in assimp's glTF importer: only tested formats are loaded.
  const auto path = std::filesystem::temp_directory_path() / "ps_mesh_test.gltf";
  std::ofstream(path) << "{}";
  Result<Mesh> mesh = load_mesh_file(path.string());
  ASSERT_FALSE(mesh);
  EXPECT_NE(mesh.error().message.find("format '.gltf' is not supported (supported: .obj, .ply, .stl, .off, .blend)"),
            std::string::npos) << mesh.error().message;
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace ps
