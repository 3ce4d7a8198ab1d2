// The haptic scene: what the proxy collides with, built once from a parsed Scene and owned by
// the haptic side (CPU memory only; queried at 1 kHz without GL and without waiting for a
// frame). Planes, spheres, boxes and tori are analytic (closest point in closed form in the
// shape's local frame); meshes and height fields are the triangles the renderer draws
// (scene/mesh.h: build_surface_mesh) in an Embree BVH (world/mesh_bvh.h). Surfaces with
// `touchable = false` are left out, and so are penetrable materials (the proxy passes through
// them); invisible ones are in (a hidden object is felt). Touchable penetrable spheres, boxes
// and tori are kept apart as volumes (medium_at: closed-form inside tests); penetrable planes
// (no inside), meshes and height fields are not felt at all (docs/haptics.md says why).
// closest() and medium_at() are const, thread-safe and allocation-free. docs/haptics.md,
// "Haptic geometry". A button (world/buttons.h) is a hole in the face it sits in: closest()
// drops that face's points inside the button's rectangle for a query point over the button and
// offers the pocket behind it instead.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/result.h"
#include "scene/mesh.h"
#include "scene/scene.h"
#include "world/buttons.h"
#include "world/fields.h"
#include "world/mesh_bvh.h"
#include "fourd/rolling.h"
#include "fourd/suggestion.h"
#include "fourd/touch.h"

namespace ps::world {

struct Contact {
  bool hit = false;
  int surface = -1;                // index into Scene::surfaces
  glm::dvec3 point{0.0};           // closest surface point, mm
  glm::dvec3 normal{0.0, 0.0, 1.0};         // geometric outward normal there
  glm::dvec3 shaded_normal{0.0, 0.0, 1.0};  // force-shading normal (== normal on analytic shapes)
  double distance_mm = 0.0;
  std::uint32_t facets_visited = 0;  // mesh triangles examined by this query (local model)
  MeshHit mesh_hit;                  // the mesh hit (a hint for the next query nearby)
  // A surface embedded in 4D (type = "fourd", docs/fourd.md): the 4D depth w at `point`. As a
  // hint, with `surface` the fourd surface the proxy keeps to: the next query of that surface
  // sees only facets whose w meets eq. 4's window around w4 (w4_pre: the w before it).
  bool has_w4 = false;
  double w4 = 0.0, w4_pre = 0.0;
  int fourd_facet = -1;  // the fourd surface's facet (fourd::FourdTouch) the point lies on
};

// Shapes are rotated with scene/mesh.h's euler_xyz_deg, the renderer's own convention, so an
// analytic shape sits exactly where its render mesh is drawn (tests/world checks both agree).
using ps::euler_xyz_deg;

// The rolling manifold's screen centre and direction toward the viewer for a camera (its
// target; from the target toward its eye, orthographic cameras alike).
fourd::ViewAxes view_axes_of(const Camera& camera);

class HapticScene {
 public:
  // Errors: a mesh or height field that cannot be loaded ("<scene>:<line>: ..."), Embree failures.
  static Result<HapticScene> build(const Scene& scene);

  // Closest point on any touchable surface within max_distance_mm of p (hit = false if none).
  // `hint`: an earlier Contact near p (MeshBvh::closest); same result, fewer facets examined.
  Contact closest(const glm::dvec3& p, double max_distance_mm, const Contact* hint = nullptr) const;

  // The penetrable volume (water, thick fluid) whose inside holds p, as a surface index; -1 if
  // none. Overlapping volumes: the first in scene order.
  int medium_at(const glm::dvec3& p) const;
  // Largest magnetic_range_mm over the touchable magnetic materials (magnetic_force_n > 0);
  // 0 when none is magnetic, and the loop skips its magnetic query.
  double max_magnetic_range_mm() const { return max_magnetic_range_mm_; }

  const HapticMaterial& material(int surface) const;  // that surface's feel
  const FieldSet& fields() const { return fields_; }       // [[fields]]
  const std::vector<Body>& bodies() const { return bodies_; }  // [[bodies]], as specified
  // [[buttons]]: their geometry (the hole and pocket closest() sees), their actions as written
  // and resolved (Scene::buttons), and the names their flag actions toggle (Scene::flags).
  const std::vector<ButtonShape>& button_shapes() const { return button_shapes_; }
  const std::vector<Button>& buttons() const { return buttons_; }
  const std::vector<std::string>& flags() const { return flags_; }
  const Navigation& navigation() const { return navigation_; }  // [navigation] (Field's box)
  double probe_radius_mm() const { return probe_radius_mm_; }
  std::size_t analytic_count() const { return shapes_.size(); }
  // Overall model: the BVH's triangles and those of the surfaces embedded in 4D.
  std::size_t triangle_count() const {
    std::size_t n = meshes_.triangle_count();
    for (const FourdShape& f : fourd_) n += f.touch.facet_count();
    return n;
  }
  const MeshBvh& meshes() const { return meshes_; }
  // The haptic geometry of surface `surface` if it is embedded in 4D (type fourd), else null.
  const fourd::FourdTouch* fourd_touch(int surface) const {
    for (const FourdShape& f : fourd_)
      if (f.surface == surface) return &f.touch;
    return nullptr;
  }
  // Its force-suggestion gains (eq. 5); off for any other surface.
  fourd::SuggestionParams fourd_suggestion(int surface) const {
    for (const FourdShape& f : fourd_)
      if (f.surface == surface) return f.suggestion;
    return {};
  }
  // Its rolling manifold (Hanson & Zhang §6, fourd/rolling.h); off for any other surface.
  fourd::RollParams fourd_roll(int surface) const {
    for (const FourdShape& f : fourd_)
      if (f.surface == surface) return f.roll;
    return {};
  }
  bool any_fourd_roll() const { return any_roll_; }  // asked twice a tick: kept, not searched
  // The scene file's camera as the device's workspace sees it: the screen centre and the
  // direction toward the viewer (the rolling manifold's default until the renderer publishes
  // the camera it draws with).
  const fourd::ViewAxes& view_axes() const { return view_axes_; }

 private:
  struct Shape {
    SurfaceType type;
    int surface;
    glm::dmat3 rotation;   // local -> world
    glm::dvec3 center;     // mm
    glm::dvec3 size;       // plane: (x, y, -); box: edges; sphere: (r, -, -); torus: (R, r, -)
    double bound_mm;       // radius of a bounding sphere around center
  };
  // Frame, size and bounding radius of an analytic shape (sphere, box, torus, plane).
  static Shape make_shape(const Surface& s, int index);
  Contact closest_analytic(const Shape& s, const glm::dvec3& p) const;
  static bool inside(const Shape& s, const glm::dvec3& p);
  // build(): surface `index` into its material and its model (shape, volume, mesh or 4D sheet).
  Status add_surface(const Scene& scene, int index);
  Status add_fourd(const Surface& s, int index, const std::string& where);
  const ButtonShape* button_over(const glm::dvec3& p) const;  // the first button p is over, if any

  // type = "fourd": its projected triangles with their 4D depth (fourd/touch.h), kept out of
  // the BVH so a query can see only the proxy's own sheet (continuity: eq. 4's window).
  struct FourdShape {
    int surface;
    // fourd_local_model: "continuity" keeps to the sheet by eq. 4's w window, "adjacency" by the
    // mesh walk (FourdTouch::closest_adjacent); "nearest" does not keep to it.
    fourd::LocalModelKind model;
    fourd::FourdTouch touch;
    fourd::SuggestionParams suggestion;  // eq. 5 (fourd/suggestion.h)
    fourd::RollParams roll;              // Hanson & Zhang §6 (fourd/rolling.h)
  };
  // closest(): the sheet's closest point within `limit`, kept to the hint's sheet by its local model.
  fourd::TouchHit touch_sheet(const FourdShape& f, const glm::dvec3& p, double limit, double max_distance_mm,
                              const Contact* hint) const;
  fourd::ViewAxes view_axes_;
  bool any_roll_ = false;  // some fourd surface has fourd_roll on
  // "adjacency": how far along the surface the walk from the sheet's facet goes at least (the
  // local models' radius, fourd/local_model.h).
  static constexpr double kAdjacencyRadiusMm = 20.0;
  std::vector<FourdShape> fourd_;
  std::vector<Shape> shapes_;
  std::vector<Shape> volumes_;  // penetrable spheres, boxes, tori: felt by medium_at()
  MeshBvh meshes_;
  std::vector<int> mesh_surface_;        // MeshBvh mesh index -> surface index
  std::vector<HapticMaterial> materials_;  // per surface index
  double probe_radius_mm_ = 0.0;
  double max_magnetic_range_mm_ = 0.0;
  FieldSet fields_;
  std::vector<Body> bodies_;
  std::vector<ButtonShape> button_shapes_;
  std::vector<Button> buttons_;
  std::vector<std::string> flags_;
  Navigation navigation_;
};

}  // namespace ps::world
