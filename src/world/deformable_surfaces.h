// Every deformable surface of a scene (world/deformable.h), stepped together on one session clock
// with the drawn probe pressing them. No GL. The world owns the stepping: settled_deformables()
// settles a scene's surfaces under its probe (what `render` shows), and a session steps them each
// frame before it is drawn (frame/haptic_frame.h step_deformation). The renderer only draws them:
// it uploads each surface whose version (drawn()) changed since its last upload. The haptic scene keeps
// the rest shapes (the deformation is graphical, A Virtual Universe §6).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "core/result.h"
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

  struct Drawn {
    int surface = -1;
    const Mesh* mesh = nullptr;  // the drawn mesh now
    std::uint64_t version = 0;   // steps that changed it so far
  };
  // Every deformable surface's drawn mesh and how many steps have changed it (a drawer uploads
  // the mesh when the version is not the one it uploaded last).
  std::vector<Drawn> drawn() const;
  // The drawn mesh of scene surface `surface` now; null if not deformable. Its bounds_min/max stay
  // the rest mesh's (the renderer's culling bounds): no step rewrites them.
  const Mesh* mesh(int surface) const;
  // The welded vertices of scene surface `surface` now (world mm); empty if not deformable.
  std::vector<glm::dvec3> positions(int surface) const;

 private:
  struct Record {
    int surface = -1;
    Mesh mesh;  // rest topology, deformed positions and normals
    std::shared_ptr<Deformable> sim;
    std::uint64_t version = 0;  // steps that rewrote the mesh
  };
  std::vector<Record> surfaces_;
  double time_s_ = -1.0;  // < 0: the clock is not set yet
  DeformationStats stats_;
};

// The deformable surfaces of `scene` (Surface::deform.enabled), each built as it is drawn
// (build_drawn_surface_mesh) and settled for 1 s under the scene's probe, held still: the dent
// `render` shows. Null when the scene has none; a mesh that cannot be built is an error.
Result<std::shared_ptr<DeformableSurfaces>> settled_deformables(const Scene& scene);

}  // namespace ps::world
