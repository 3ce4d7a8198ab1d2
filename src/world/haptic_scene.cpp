#include "world/haptic_scene.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "fourd/fourd_mesh.h"
#include "scene/mesh.h"
#include "world/shapes.h"

namespace ps::world {


namespace {

bool is_magnetic(const HapticMaterial& m) {
  return !m.penetrable && m.magnetic_force_n > 0.0 && m.magnetic_range_mm > 0.0;
}

// The best contact so far becomes this one; the search limit shrinks to its distance.
void take(Contact& best, double& limit, int surface, const glm::dvec3& point, const glm::dvec3& normal,
          const glm::dvec3& shaded_normal, double distance_mm) {
  best.hit = true;
  best.surface = surface;
  best.point = point;
  best.normal = normal;
  best.shaded_normal = shaded_normal;
  best.distance_mm = distance_mm;
  limit = distance_mm;
}

}  // namespace

HapticScene::Shape HapticScene::make_shape(const Surface& s, int index) {
  Shape shape{s.type, index, euler_xyz_deg(s.rotation_deg), s.center, glm::dvec3(0.0), 0.0};
  switch (s.type) {
    case SurfaceType::kPlane:
      shape.size = {s.size_mm.x, s.size_mm.y, 0.0};
      shape.bound_mm = 0.5 * glm::length(s.size_mm);
      break;
    case SurfaceType::kSphere:
      shape.size = {s.radius_mm, 0.0, 0.0};
      shape.bound_mm = s.radius_mm;
      break;
    case SurfaceType::kBox:
      shape.size = s.box_size_mm;
      shape.bound_mm = 0.5 * glm::length(s.box_size_mm);
      break;
    case SurfaceType::kTorus:
      shape.size = {s.radius_mm, s.minor_radius_mm, 0.0};
      shape.bound_mm = s.radius_mm + s.minor_radius_mm;
      break;
    case SurfaceType::kHeightField:
    case SurfaceType::kMesh:
    case SurfaceType::kFourd: break;
  }
  return shape;
}

fourd::ViewAxes view_axes_of(const Camera& camera) {
  fourd::ViewAxes a;
  a.centre_ws = camera.target;
  const glm::dvec3 back = camera.position - camera.target;
  const double len = glm::length(back);
  if (len > 0.0 && std::isfinite(len)) a.toward_viewer_ws = back / len;
  return a;
}

Result<HapticScene> HapticScene::build(const Scene& scene) {
  HapticScene out;
  out.probe_radius_mm_ = scene.probe.radius_mm;
  out.fields_ = FieldSet(scene.fields);
  out.bodies_ = scene.bodies;
  out.buttons_ = scene.buttons;
  out.flags_ = scene.flags;
  out.navigation_ = scene.navigation;
  out.view_axes_ = view_axes_of(scene.camera);
  for (std::size_t i = 0; i < scene.surfaces.size(); ++i) {
    const int b = scene.surfaces[i].button;
    if (b >= 0) out.button_shapes_.push_back(ButtonShape::make(scene.buttons[static_cast<std::size_t>(b)], static_cast<int>(i)));
  }
  for (std::size_t i = 0; i < scene.surfaces.size(); ++i)
    if (Status st = out.add_surface(scene, static_cast<int>(i)); !st) return st.error();
  if (Status st = out.meshes_.commit(); !st) return st.error();
  return out;
}

Status HapticScene::add_surface(const Scene& scene, int index) {
  const Surface& s = scene.surfaces[static_cast<std::size_t>(index)];
  const std::size_t m = static_cast<std::size_t>(s.material_index);
  materials_.push_back(m < scene.materials.size() ? scene.materials[m].haptic : HapticMaterial{});
  const HapticMaterial& feel = materials_.back();
  if (!s.touchable) return ok_status();  // seen only
  const bool analytic = s.type != SurfaceType::kMesh && s.type != SurfaceType::kHeightField &&
                        s.type != SurfaceType::kFourd;  // fourd: its projected triangles
  if (feel.penetrable) {
    // A penetrable material (water, thick fluid) lets the proxy through: it acts by its
    // viscosity inside (medium_at), not as a constraint. A plane has no inside; a mesh would
    // need a ray-parity test per tick and is left out (docs/haptics.md, limitation).
    if (analytic && s.type != SurfaceType::kPlane) volumes_.push_back(make_shape(s, index));
    return ok_status();
  }
  if (is_magnetic(feel)) max_magnetic_range_mm_ = std::max(max_magnetic_range_mm_, feel.magnetic_range_mm);
  if (analytic) {
    shapes_.push_back(make_shape(s, index));
    return ok_status();
  }
  const std::string where = scene.path + ":" + std::to_string(s.line) + ": ";
  if (s.type == SurfaceType::kFourd) return add_fourd(s, index, where);
  // Height field: the rendered triangles, an image has no closed form. Mesh: the triangles.
  Result<Mesh> mesh = build_surface_mesh(s);
  if (!mesh) return make_error(where + mesh.error().message);
  if (Status st = meshes_.add_mesh(mesh.value()); !st) return make_error(where + st.error().message);
  mesh_surface_.push_back(index);
  return ok_status();
}

Status HapticScene::add_fourd(const Surface& s, int index, const std::string& where) {
  Result<fourd::FourdMesh> f = fourd::build_fourd_mesh(s.fourd);
  if (!f) return make_error(where + f.error().message);
  fourd_.push_back({index, s.fourd.local_model,
                    fourd::FourdTouch(f.value(), s.scale, euler_xyz_deg(s.rotation_deg), s.center),
                    {s.fourd.suggest_kp_n_per_mm, s.fourd.suggest_kv_n_s_per_mm, s.fourd.suggest_lookahead_s},
                    s.fourd.roll});
  any_roll_ = any_roll_ || s.fourd.roll.on;
  return ok_status();
}

bool HapticScene::inside(const Shape& s, const glm::dvec3& p) {
  const glm::dvec3 q = glm::transpose(s.rotation) * (p - s.center);  // shape's local frame
  switch (s.type) {
    case SurfaceType::kSphere: return glm::dot(q, q) < s.size.x * s.size.x;
    case SurfaceType::kBox: {
      const glm::dvec3 a = glm::abs(q) - 0.5 * s.size;
      return a.x < 0.0 && a.y < 0.0 && a.z < 0.0;
    }
    case SurfaceType::kTorus: {  // distance from the ring circle below the tube radius
      const double ring = std::sqrt(q.x * q.x + q.y * q.y) - s.size.x;
      return ring * ring + q.z * q.z < s.size.y * s.size.y;
    }
    case SurfaceType::kPlane:
    case SurfaceType::kHeightField:
    case SurfaceType::kMesh:
    case SurfaceType::kFourd: break;
  }
  assert(false && "HapticScene::inside: only spheres, boxes and tori are kept as volumes");
  return false;
}

int HapticScene::medium_at(const glm::dvec3& p) const {
  for (const Shape& v : volumes_) {
    if (glm::length(p - v.center) < v.bound_mm && inside(v, p)) return v.surface;
  }
  return -1;
}

Contact HapticScene::closest_analytic(const Shape& s, const glm::dvec3& p) const {
  const glm::dvec3 local = glm::transpose(s.rotation) * (p - s.center);
  SurfacePoint sp;
  switch (s.type) {
    case SurfaceType::kPlane: sp = closest_on_plane(local, {s.size.x, s.size.y}); break;
    case SurfaceType::kSphere: sp = closest_on_sphere(local, s.size.x); break;
    case SurfaceType::kBox: sp = closest_on_box(local, s.size); break;
    case SurfaceType::kTorus: sp = closest_on_torus(local, s.size.x, s.size.y); break;
    case SurfaceType::kHeightField:
    case SurfaceType::kMesh:
    case SurfaceType::kFourd: assert(false && "HapticScene::closest_analytic: meshes live in the BVH"); break;
  }
  Contact c;
  c.hit = true;
  c.surface = s.surface;
  c.point = s.rotation * sp.point + s.center;
  c.normal = c.shaded_normal = s.rotation * sp.normal;
  c.distance_mm = glm::length(p - c.point);
  return c;
}

const ButtonShape* HapticScene::button_over(const glm::dvec3& p) const {
  for (const ButtonShape& b : button_shapes_)
    if (b.over(b.to_local(p))) return &b;
  return nullptr;
}

fourd::TouchHit HapticScene::touch_sheet(const FourdShape& f, const glm::dvec3& p, double limit,
                                         double max_distance_mm, const Contact* hint) const {
  const bool on_sheet = hint != nullptr && hint->has_w4 && hint->surface == f.surface;
  if (on_sheet && f.model == fourd::LocalModelKind::kAdjacency && hint->fourd_facet >= 0) {
    // Mesh adjacency: the walk from the sheet's last facet must reach every facet of the
    // sheet this query could return (within max_distance of p), hence at least twice that.
    return f.touch.closest_adjacent(p, limit, hint->fourd_facet, hint->point,
                                    std::max(kAdjacencyRadiusMm, 2.0 * max_distance_mm));
  }
  fourd::WWindow window;
  if (on_sheet && f.model == fourd::LocalModelKind::kContinuity) window = f.touch.window(hint->w4, hint->w4_pre);
  return f.touch.closest(p, limit, window);
}

Contact HapticScene::closest(const glm::dvec3& p, double max_distance_mm, const Contact* hint) const {
  Contact best;
  double limit = max_distance_mm;
  // Over a button (buttons do not overlap: the first one p is over), the face's points in its
  // rectangle are the hole; the pocket behind it stands in for them.
  const ButtonShape* button = button_over(p);
  auto in_hole = [button](const glm::dvec3& point) { return button != nullptr && button->in_hole(button->to_local(point)); };
  if (button != nullptr) {
    const SurfacePoint sp = button->pocket_closest(button->to_local(p));
    const glm::dvec3 point = button->rotation * sp.point + button->center;
    const double d = glm::length(p - point);
    const glm::dvec3 normal = button->rotation * sp.normal;
    if (d <= limit) take(best, limit, button->surface, point, normal, normal, d);
  }
  for (const Shape& s : shapes_) {
    // Whole shape farther than the best so far: skip it without the exact query.
    if (glm::length(p - s.center) - s.bound_mm > limit) continue;
    const Contact c = closest_analytic(s, p);
    if (c.distance_mm <= limit && !in_hole(c.point)) {
      best = c;
      limit = c.distance_mm;
    }
  }
  const MeshHit h = meshes_.closest(p, limit, hint != nullptr ? &hint->mesh_hit : nullptr);
  best.facets_visited = h.visited;
  if (h.hit) best.mesh_hit = h;
  if (h.hit && h.distance_mm <= limit && !in_hole(h.point))
    take(best, limit, mesh_surface_[h.mesh], h.point, h.face_normal, h.shaded_normal, h.distance_mm);
  for (const FourdShape& f : fourd_) {
    const fourd::TouchHit t = touch_sheet(f, p, limit, max_distance_mm, hint);
    best.facets_visited += t.visited;
    if (!t.hit || t.distance_mm > limit || in_hole(t.point)) continue;
    take(best, limit, f.surface, t.point, t.normal, t.shaded_normal, t.distance_mm);
    best.has_w4 = true;
    best.w4 = t.w;
    best.fourd_facet = t.facet;
  }
  return best;
}

const HapticMaterial& HapticScene::material(int surface) const {
  assert(surface >= 0 && static_cast<std::size_t>(surface) < materials_.size() &&
         "HapticScene::material: surface index out of range (a Contact with hit = false?)");
  return materials_[static_cast<std::size_t>(surface)];
}

}  // namespace ps::world
