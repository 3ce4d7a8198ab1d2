// CPU ray-cast of the scene camera against the surfaces' own triangle meshes (the meshes the
// GPU rasterises, so tessellation is not an error source), in double precision. Used by the
// accuracy tests as the per-pixel ground truth for world position and interpolated normal.
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "scene/mesh.h"
#include "scene/scene.h"

namespace ps::test {

struct Ray {
  glm::dvec3 origin{0.0}, dir{0.0, 0.0, -1.0};  // dir unit
};

struct SurfaceHit {
  glm::dvec3 position{0.0};  // mm, world
  glm::dvec3 normal{0.0};    // unit, facing the ray origin (as gl_FrontFacing flips it)
  double t = 0.0;
};

// Ray through the centre of pixel (px, py), row 0 = top, of the scene's camera.
Ray pixel_ray(const Scene& scene, int px, int py);

// Every surface mesh of the scene (world space), built as the renderer builds them.
std::vector<Mesh> scene_meshes(const Scene& scene);

// Nearest hit over all meshes (Moller-Trumbore, barycentric normal interpolation).
std::optional<SurfaceHit> raycast(const std::vector<Mesh>& meshes, const Ray& ray);

}  // namespace ps::test
