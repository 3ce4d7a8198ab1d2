// Every deformable surface of a scene (world/deformable.h), stepped together on one session clock
// with the drawn probe pressing them. No GL: the renderer uploads the meshes a step changed
// (changed()); the haptic scene keeps the rest shapes (the deformation is graphical, seed 002 §6).
#pragma once

#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "scene/mesh.h"
#include "scene/scene.h"
#include "world/deformable.h"

namespace ps::world {

// What the last deformation step did (all deformable surfaces together).
struct DeformationStats {
  int surfaces = 0;               // deformable surfaces in the scene
  int substeps = 0;
  int constrained = 0;            // vertices held on the probe's surface
  double max_displacement_mm = 0.0;
  bool finite = true;
  int uploaded = 0;               // surfaces whose vertices changed (and were uploaded) this step
};

class DeformableSurfaces {
 public:
  // Adds scene surface `surface`, drawn as `rest` (world mm): returns the mesh to draw it with (rest
  // subdivided to the params' max_edge_mm), whose positions and normals each step rewrites.
  const Mesh& add(int surface, const Mesh& rest, const DeformParams& params);
  bool empty() const { return surfaces_.empty(); }

  // Steps every surface dt_s seconds with the probe drawn as `probe` (a sphere probe, or a capsule's
  // tip cap; a mesh probe does not press: its bounding sphere would dent far more than it touches).
  const DeformationStats& step(double dt_s, const Probe& probe);
  // Steps to session time `time_s` (the first time only sets the clock; non-finite: no step).
  const DeformationStats& advance(double time_s, const Probe& probe);
  const DeformationStats& stats() const { return stats_; }

  struct Changed {
    int surface = -1;
    const Mesh* mesh = nullptr;
  };
  // The surfaces whose drawn mesh the last step() changed (none after an advance() that did not step).
  std::vector<Changed> changed() const;
  // The welded vertices of scene surface `surface` now (world mm); empty if not deformable.
  std::vector<glm::dvec3> positions(int surface) const;

 private:
  struct Record {
    int surface = -1;
    Mesh mesh;  // rest topology, deformed positions and normals
    std::shared_ptr<Deformable> sim;
    bool changed = false;
  };
  std::vector<Record> surfaces_;
  double time_s_ = -1.0;  // < 0: the clock is not set yet
  DeformationStats stats_;
};

}  // namespace ps::world
