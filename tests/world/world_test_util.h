// Scenes built in code for the haptic-geometry tests, and a coarse mesh written as an OBJ file
// so mesh surfaces go through the same loader (assimp) as a scene file's.
#pragma once

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "scene/mesh_procedural.h"
#include "scene/scene.h"

namespace ps::test {

inline Scene scene_with(double probe_radius_mm, std::initializer_list<Surface> surfaces) {
  Scene sc;
  sc.path = "test.toml";
  sc.probe.radius_mm = probe_radius_mm;
  Material m;
  m.name = "test";
  m.haptic.static_friction = m.haptic.dynamic_friction = 0.0;  // frictionless unless a test says
  sc.materials.push_back(m);
  sc.surfaces = surfaces;
  return sc;
}

inline Surface analytic(SurfaceType type, glm::dvec3 center = glm::dvec3(0.0), glm::dvec3 rotation_deg = glm::dvec3(0.0)) {
  Surface s;
  s.type = type;
  s.center = center;
  s.rotation_deg = rotation_deg;
  return s;
}

// A UV sphere of `resolution` segments as an OBJ file in the test's binary dir; returns its path.
inline std::string write_sphere_obj(const std::string& name, double radius_mm, int resolution) {
  const Mesh m = mesh_detail::make_sphere(radius_mm, resolution);
  const std::string path = std::string(PS_BINARY_DIR) + "/tests/world/" + name + ".obj";
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::ofstream out(path);
  for (const glm::vec3& p : m.positions) out << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
  for (std::size_t i = 0; i + 2 < m.indices.size(); i += 3)
    out << "f " << m.indices[i] + 1 << ' ' << m.indices[i + 1] + 1 << ' ' << m.indices[i + 2] + 1 << '\n';
  return path;
}

inline Surface mesh_surface(const std::string& file, glm::dvec3 center = glm::dvec3(0.0), double scale = 1.0) {
  Surface s;
  s.type = SurfaceType::kMesh;
  s.mesh_file = file;
  s.center = center;
  s.scale = scale;
  return s;
}

inline const char* kSuzanne = "/usr/share/assimp/models/BLEND/Suzanne_248.blend";  // assimp-testmodels

}  // namespace ps::test
