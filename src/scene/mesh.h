// Triangle meshes for surfaces and mesh probes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/result.h"
#include "scene/scene.h"

namespace ps {

struct Mesh {
  std::vector<glm::vec3> positions;  // mm, world space
  std::vector<glm::vec3> normals;    // unit, outward
  std::vector<std::uint32_t> indices;  // triangles, counter-clockwise seen from outside
  // Optional per-vertex colour multiplying the material's albedo (linear RGB); empty = white.
  // Surfaces embedded in 4D carry their 4D-depth colour here (docs/fourd.md).
  std::vector<glm::vec3> colors;
  // Optional per-vertex 4D depth w of a surface embedded in 4D (docs/fourd.md); empty = none.
  // The renderer keeps the pseudo-shadow to the probe's sheet with it.
  std::vector<float> w4;
  glm::dvec3 bounds_min{0.0}, bounds_max{0.0};  // world-space AABB
};

// Hard limit so a hostile file cannot exhaust memory (documented in docs/scene-format.md).
inline constexpr std::size_t kMaxMeshTriangles = 4'000'000;
// Mesh files larger than this are refused before assimp reads them.
inline constexpr std::uintmax_t kMaxMeshFileBytes = 256u << 20;

// A surface's rotation: XYZ Euler in degrees, rotate about X first, then Y, then Z
// (R = Rz * Ry * Rx). The renderer's meshes and the haptic geometry both use this one.
glm::dmat3 euler_xyz_deg(const glm::dvec3& rotation_deg);

// World-space mesh of a scene surface (procedural shapes tessellated at surface.resolution;
// height fields from the grey image; meshes through assimp, transformed by centre/rotation/scale).
Result<Mesh> build_surface_mesh(const Surface& surface);
// The mesh a surface is drawn with: build_surface_mesh with Surface::visual_stretch applied (the
// renderer's meshes and the deformable surfaces' rest shapes; the haptic scene keeps the unstretched one).
Result<Mesh> build_drawn_surface_mesh(const Surface& surface);

// Loads all meshes of a file through assimp and merges them (no transform applied).
// Errors name the file: "<path>: cannot load mesh: <assimp's reason>", empty meshes refused.
Result<Mesh> load_mesh_file(const std::string& path);

// Applies scale, then XYZ Euler rotation (degrees), then translation; recomputes bounds.
void transform_mesh(Mesh& mesh, double scale, const glm::dvec3& rotation_deg,
                    const glm::dvec3& translation);

}  // namespace ps
