// The bendable polygons of A Virtual Universe §6: a surface's drawn vertices tied by springs to
// base points (where they rest) and to their neighbours, pushed in by the probe and drawn deformed.
// The deformation is graphical, as in A Virtual Universe: the haptic scene keeps the rest shape
// (the god-object and its force are unchanged), and what a person sees is a dent that follows the
// drawn probe, so the probe never gets "lost within a compliant object". docs/universe.md, "Poly".
//
// Model, per welded vertex i with displacement u_i = x_i - b_i from its base point b_i:
//   m u_i'' = -k_b u_i + k_n sum_{j ~ i} (u_j - u_i) - c u_i'
// (neighbour springs act on the displacement difference: a linear, rotation-free spring web that
// spreads a dent smoothly). Semi-implicit Euler with the damping implicit, in substeps no longer
// than 0.5 / omega_max (omega_max^2 = (k_b + 2 deg_max k_n) / m, the web's highest mode), so it
// is stable for any parameters. After every substep the probe is a hard constraint: a vertex
// inside the probe sphere is moved onto it, kContactOverlapMm inside its surface, and loses its
// velocity into the probe. (Exactly on the surface, the pseudo-shadow's distance in the dent
// would be 0 within the depth map's precision and the contact patch would break up into specks
// of "contact" and "almost"; a tenth of a millimetre in, the whole dent reads as contact.) Every
// displacement is clamped to max_mm (the bound a violent trajectory cannot break).
// Windowed (A Virtual Universe §6: "windowing of the local area"): each step simulates only the
// vertices that are displaced or moving (above 1e-4 mm or 1e-3 mm/s: a tenth of a micrometre is far
// below a pixel at any zoom a person uses) or near the probe, and three rings of their neighbours;
// the rest are exactly at rest, and a vertex that has come back below those is put exactly at rest.
// A press costs its neighbourhood, not the mesh.
// Normals: each drawn vertex keeps its rest normal (the file's, Gouraud across a facet) turned by
// the change of its welded neighbourhood's area-weighted normal, so at rest the surface shades as
// drawn before and a dent shades as a dent.
// No GL: the renderer owns one per deformable surface and uploads positions and normals.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/mesh.h"
#include "scene/scene.h"

namespace ps::world {

inline constexpr double kContactOverlapMm = 0.15;

struct DeformStep {
  int substeps = 0;
  int constrained = 0;         // vertices on the probe's surface after the last substep
  double max_displacement_mm = 0.0;
};

class Deformable {
 public:
  // `rest`: the drawn mesh at rest (world mm). Vertices at the same position (to 1e-4 mm) are
  // welded (files split them at seams and hard edges), so no crack opens along a seam.
  Deformable(const Mesh& rest, const DeformParams& params);

  // Advances dt_s seconds (0..0.1 s; longer is clamped) with the drawn probe, a sphere of
  // `radius_mm` at `centre_mm`, pushing the surface (a non-finite centre: no probe).
  DeformStep step(double dt_s, const glm::dvec3& centre_mm, double radius_mm);
  // Back to rest, at rest.
  void reset();

  // `mesh` (the rest mesh this was built from) gets the deformed positions and normals.
  void write(Mesh& mesh) const;
  std::size_t active_count() const { return active_.size(); }  // simulated by the last step

  std::size_t welded_count() const { return base_.size(); }
  const std::vector<glm::dvec3>& positions() const { return x_; }   // welded, world mm
  const std::vector<glm::dvec3>& base_points() const { return base_; }
  double max_displacement_mm() const;
  bool finite() const;
  double stable_substep_s() const { return substep_s_; }

 private:
  DeformParams params_;
  std::vector<glm::dvec3> base_, x_, v_;
  std::vector<std::uint32_t> weld_;        // mesh vertex -> welded vertex
  std::vector<std::uint32_t> nbr_begin_, nbr_;  // CSR adjacency of welded vertices
  std::vector<std::uint32_t> triangles_;   // welded indices, 3 per triangle
  std::vector<glm::dvec3> force_;          // scratch
  std::vector<glm::dvec3> rest_area_normal_;  // welded, area-weighted, at rest
  std::vector<glm::vec3> rest_normal_;     // mesh vertex normals as drawn at rest
  std::vector<std::uint32_t> active_;      // welded vertices simulated this step
  std::vector<std::uint8_t> is_active_;
  double mean_edge_mm_ = 1.0;
  double substep_s_ = 1e-3;
  std::vector<glm::dvec3> area_normals() const;
  // The constructor's first steps: base_ and weld_ (rest vertex -> welded vertex); then the
  // welded triangles and the neighbour lists (CSR), returning the largest degree.
  void weld(const Mesh& rest);
  std::size_t build_adjacency(const Mesh& rest);
  void collect_active(const glm::dvec3& centre_mm, double radius_mm, bool probe);
  void accumulate_forces();
  bool hold_out_of_probe(std::uint32_t i, const glm::dvec3& centre_mm, double radius_mm);
};

// `mesh` with every triangle split into four (edge midpoints shared by the triangles that share
// the edge; a midpoint's normal the normalised mean of its ends') until no edge is longer than
// max_edge_mm, at most 3 times and while the result stays under max_triangles.
Mesh subdivide(const Mesh& mesh, double max_edge_mm, std::size_t max_triangles = 400'000);

// Where the probe is drawn when it presses a deformable surface (A Virtual Universe §6, the
// pseudo-haptic way): the god-object `proxy_mm` stays on the felt rest surface while the hand
// (`device_mm`, the filtered device) goes in; the drawn probe goes in by the share of that depth a
// spring of the surface's stiffness k leaves to the hand's coupling k_c: k_c / (k_c + k) (the
// buttons' rule, so a softer surface dents deeper), at most the surface's deform max_mm and half
// the probe radius. Elsewhere: `proxy_mm` unchanged.
glm::dvec3 pressed_position(const Scene& scene, int contact_surface, const glm::dvec3& proxy_mm,
                            const glm::dvec3& device_mm, double coupling_n_per_mm);

}  // namespace ps::world
