// A surface embedded in R^4, tessellated, rotated in 4D and projected to 3D (docs/fourd.md):
// each vertex keeps its 4D point, its 3D image and its 4D depth w. Triangles know their three
// neighbours across edges, found by welding vertices by their 4D position: that is the
// surface's own topology (the torus's and the sphere's seams, the Roman surface's RP^2
// identification), not the self-intersecting 3D image's. The haptic local model
// (fourd/local_model.h) walks these neighbours. Built once per scene (re)load; read-only after.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/result.h"
#include "fourd/spec.h"

namespace ps::fourd {

struct Vertex4 {
  glm::dvec4 p4{0.0};  // rotated 4D point
  glm::dvec3 p3{0.0};  // its 3D image (4D units; the scene's `scale` makes it mm)
  double w = 0.0;      // 4D depth (p4.w)
  glm::dvec2 uv{0.0};  // surface parameters in [0, 1]^2
};

struct FourdMesh {
  Spec spec;
  int nu = 0, nv = 0;                   // grid cells; vertex (i, j) is vertices[j * (nu + 1) + i]
  std::vector<Vertex4> vertices;
  std::vector<glm::uvec3> triangles;     // counter-clockwise in (u, v); degenerate ones dropped
  std::vector<glm::ivec3> neighbours;    // across edge k = (t[k], t[(k+1)%3]); -1: border (none here)
  std::vector<glm::dvec3> normals;       // per vertex: unit normal of the 3D image
  double w_min = 0.0, w_max = 0.0;

  // Hanson & Zhang's "polygon number" (Table 1): grid quads, each drawn as two triangles.
  int polygons() const { return nu * nv; }
  // Facet f's w range and its 3D bounding sphere (for the local model's radius test).
  double tri_w_min(std::size_t f) const;
  double tri_w_max(std::size_t f) const;
};

// Tessellates, rotates and projects. Errors: a perspective eye inside the rotated surface (a
// vertex with w >= 0.95 eye_distance; the message, worded to follow "'fourd_eye_distance' ",
// gives the surface's largest w and a value that works), grid too small.
Result<FourdMesh> build_fourd_mesh(const Spec& spec);
// Only that check, without building triangles or neighbours (cheap at any grid: the scene
// reader runs it).
Status check_eye(const Spec& spec);

// Twice the median |w change| along a mesh edge: the default w_slack of the local models
// (fourd/local_model.h says why).
double auto_w_slack(const FourdMesh& mesh);

// Closest point on triangle abc to p (Ericson, Real-Time Collision Detection §5.1.5); `bary`
// gets its barycentric coordinates.
glm::dvec3 closest_on_triangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                               glm::dvec3& bary);

// The documented colour map of 4D depth (docs/fourd.md): t = (w - w_min) / (w_max - w_min)
// from 0 (farthest from the 4D eye) to 1 (nearest): blue, cyan, green, yellow, red.
glm::dvec3 depth_colour(double t);

}  // namespace ps::fourd
