#include "haptics/force_model.h"

#include <algorithm>
#include <cmath>

#include "haptics/material_forces.h"
#include "world/god_object.h"

namespace ps {

glm::dmat3 normal_projector(const glm::dvec3& n) { return glm::outerProduct(n, n); }
glm::dmat3 tangent_projector(const glm::dvec3& n) { return glm::dmat3(1.0) - normal_projector(n); }

double spring_magnitude_n(const HapticsParams& p, double penetration_mm) {
  if (penetration_mm <= 0.0) return 0.0;
  return p.stiffness_n_per_mm * std::pow(penetration_mm, 1.0 + p.stiffness_exponent);
}

glm::dvec3 external_force_n(const HapticsParams& p, double time_s) {
  const double phase = 2.0 * 3.14159265358979323846 * p.external_frequency_hz * time_s;
  return p.external_force_n + p.external_fluctuation_n * std::sin(phase);
}

namespace {

// Friction cone on the tangent plane: the proxy is the stick point; returns the tangent force
// and moves the proxy when the cone is left (sliding at mu_d).
glm::dvec3 friction(const HapticsParams& p, const glm::dvec3& n, double normal_n,
                    const glm::dvec3& x_surface, glm::dvec3& proxy, bool& sticking) {
  const glm::dvec3 offset = tangent_projector(n) * (proxy - x_surface);  // mm, tangent only
  const double len = glm::length(offset);
  const double k = p.tangent_stiffness_n_per_mm;
  if (k <= 0.0 || len <= 0.0) { proxy = x_surface; sticking = len <= 0.0; return glm::dvec3(0.0); }
  if (k * len <= p.static_friction * normal_n) {
    sticking = true;
    proxy = x_surface + offset;
    return k * offset;
  }
  sticking = false;
  const double slide_n = p.dynamic_friction * normal_n;
  proxy = x_surface + offset * (slide_n / (k * len));
  return offset * (slide_n / len);
}

}  // namespace

ForceResult compute_force(const HapticsParams& p, const SurfaceModel& m, const glm::dvec3& x_mm,
                          const glm::dvec3& v_mm_s, const glm::dvec3& prev_proxy_mm, double time_s) {
  ForceResult out;
  out.proxy_mm = x_mm;
  glm::dvec3 f = external_force_n(p, time_s) - p.viscosity_n_s_per_mm * v_mm_s;
  const glm::dvec3 n = m.normal;
  const double r = m.valid ? m.probe_radius_mm - glm::dot(n, x_mm - m.point_mm) : 0.0;
  if (m.valid && r > 0.0) {
    out.in_contact = true;
    out.penetration_mm = r;
    out.contact_normal = n;
    const double fn = spring_magnitude_n(p, r);
    f += fn * n;
    f -= p.damping_n_s_per_mm * glm::dot(n, v_mm_s) * n;
    const glm::dvec3 x_surface = x_mm + r * n;  // device projected onto the constraint
    glm::dvec3 proxy = prev_proxy_mm;
    f += friction(p, n, fn, x_surface, proxy, out.sticking);
    out.proxy_mm = proxy;
  }
  const double len = glm::length(f);
  if (len > p.max_force_n && len > 0.0) f *= p.max_force_n / len;
  out.force_n = f;
  return out;
}

HapticsParams with_material(const HapticsParams& p, const HapticMaterial& m) {
  HapticsParams q = p;
  q.stiffness_n_per_mm = m.stiffness_n_per_mm;
  q.stiffness_exponent = m.stiffness_exponent;
  q.damping_n_s_per_mm = m.damping_n_s_per_mm;
  q.static_friction = m.static_friction;
  q.dynamic_friction = m.dynamic_friction;
  return q;
}

namespace {

// A contact as the material laws see it. A surface carries no parametrisation here, so the
// texture frame is built from the normal alone: u = world X projected onto the tangent plane
// (world Y when n lies within ~25 degrees of X, where that projection gets short), v = n x u,
// and the texture coordinates are the contact point's components along u and v. On a face
// with normal +Z this is (x, y) in mm, on any flat face a fixed frame; on curved surfaces the
// frame turns with n (docs/haptics.md, "Haptic geometry").
MaterialContact material_contact(const glm::dvec3& n, const glm::dvec3& point_mm, double distance_mm,
                                 const glm::dvec3& v_mm_s) {
  MaterialContact c;
  c.distance_mm = distance_mm;
  c.normal = n;
  const glm::dvec3 ref = std::abs(n.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
  c.tangent_u = glm::normalize(ref - glm::dot(ref, n) * n);
  c.tangent_v = glm::cross(n, c.tangent_u);
  c.surface_mm = {glm::dot(point_mm, c.tangent_u), glm::dot(point_mm, c.tangent_v)};
  c.velocity_mm_s = v_mm_s;
  return c;
}

// Magnetic pull toward the nearest surface within R + the largest magnetic range: one
// radius-limited query, none at all when no material is magnetic. Only the nearest surface
// pulls (a magnet behind a nearer plain surface is screened by it).
glm::dvec3 magnetic_pull_n(const world::HapticScene& scene, const glm::dvec3& p_mm, const glm::dvec3& v_mm_s) {
  const double reach = scene.max_magnetic_range_mm();
  if (!(reach > 0.0)) return glm::dvec3(0.0);
  const double r = scene.probe_radius_mm();
  const world::Contact c = scene.closest(p_mm, r + reach);
  if (!c.hit || !(c.distance_mm > 0.0)) return glm::dvec3(0.0);
  // Normal from the closest point to the centre: the pull aims at the nearest point, also
  // past a mesh edge where the face normal would not.
  const glm::dvec3 n = (p_mm - c.point) / c.distance_mm;
  return magnetic_force_n(scene.material(c.surface), material_contact(n, c.point, c.distance_mm - r, v_mm_s));
}

// In contact with material m along n (spring fn already known): the spring, damping, texture
// and stickiness forces; `push_n` returns the normal force friction works against.
glm::dvec3 contact_force_n(const HapticsParams& q, const HapticMaterial& m, const MaterialContact& c,
                           double fn, double& push_n) {
  const glm::dvec3& n = c.normal;
  const double damped = fn - q.damping_n_s_per_mm * glm::dot(n, c.velocity_mm_s);
  // The texture rides on the push and may at most cancel it: a surface never pulls (pulling
  // is stickiness's job). Without texture this is the plain spring-damper.
  const double texture = std::max(texture_value_n(m, c.surface_mm), -std::max(damped, 0.0));
  push_n = std::max(fn + texture, 0.0);
  return (damped + texture) * n + stickiness_force_n(m, c);
}

// -b v of the penetrable volume (water, thick fluid) holding the probe centre p; `medium` is
// its surface index, -1 (and no force) outside every volume.
glm::dvec3 medium_drag_n(const world::HapticScene& scene, const glm::dvec3& p_mm, const glm::dvec3& v_mm_s,
                         int& medium) {
  medium = scene.medium_at(p_mm);
  if (medium < 0) return glm::dvec3(0.0);
  MaterialContact inside;
  inside.distance_mm = -scene.probe_radius_mm();  // centre inside: at least R deep
  inside.velocity_mm_s = v_mm_s;
  return viscosity_force_n(scene.material(medium), inside);
}

// Touching: the material's spring along the (shaded) normal, then its friction, added to f in
// that order; friction may hold the proxy back toward last tick's place (stick_point).
void add_contact_force(const HapticsParams& p, world::GodObject& god, const world::ProxyStep& step,
                       const glm::dvec3& x_mm, const glm::dvec3& v_mm_s, double r, const glm::dvec3& stick_point,
                       glm::dvec3& f, ForceResult& out) {
  const HapticMaterial& m = god.scene().material(step.surface);
  const HapticsParams q = with_material(p, m);
  out.in_contact = true;
  out.surface = step.surface;
  out.penetration_mm = r;
  out.contact_normal = step.contact_normal;
  const glm::dvec3 n = q.force_shading ? step.shaded_normal : (step.proxy_mm - x_mm) / r;
  double push_n = 0.0;
  f += contact_force_n(q, m, material_contact(n, step.contact_point, -r, v_mm_s),
                       spring_magnitude_n(q, r), push_n);
  glm::dvec3 held = stick_point;
  f += friction(q, step.contact_normal, push_n, step.proxy_mm, held, out.sticking);
  if (held != step.proxy_mm) {
    const world::ProxyStep back = god.move(held);  // constrained: stops at any surface
    out.proxy_mm = back.proxy_mm;
    out.facets_visited += back.facets_visited;
  }
}

}  // namespace

ForceResult compute_proxy_force(const HapticsParams& p, world::GodObject& god, const glm::dvec3& x_mm,
                                const glm::dvec3& v_mm_s, double time_s, const glm::dvec3& field_force_n) {
  ForceResult out;
  glm::dvec3 f = external_force_n(p, time_s) - p.viscosity_n_s_per_mm * v_mm_s;
  const glm::dvec3 stick_point = god.proxy();  // last tick's proxy: where friction holds it
  // The coupling spring's rest offset: the proxy settles where k_c (proxy - x) balances the
  // field force (zero without fields: the goal is the device, as before).
  const glm::dvec3 goal = x_mm + field_force_n / std::max(p.coupling_n_per_mm, 1e-9);
  const world::ProxyStep step = god.move(goal);
  out.proxy_mm = step.proxy_mm;
  out.facets_visited = step.facets_visited;
  out.catching_up = step.short_of_goal;
  f += medium_drag_n(god.scene(), step.proxy_mm, v_mm_s, out.medium);
  const double r = glm::length(step.proxy_mm - x_mm);
  if (step.in_contact && r > 0.0) {
    add_contact_force(p, god, step, x_mm, v_mm_s, r, stick_point, f, out);
  } else if (!step.in_contact) {
    f += magnetic_pull_n(god.scene(), step.proxy_mm, v_mm_s);
  }
  // The field force reaches the hand through the coupling, except the part a touched surface
  // holds: its component into the surface.
  glm::dvec3 transmitted = field_force_n;
  if (step.in_contact) transmitted -= std::min(0.0, glm::dot(transmitted, step.contact_normal)) * step.contact_normal;
  f += transmitted;
  const double len = glm::length(f);
  if (len > p.max_force_n && len > 0.0) f *= p.max_force_n / len;
  out.force_n = f;
  return out;
}

SurfaceModel update_surface_model(const SurfaceModel& last, const glm::dvec3& reference_normal,
                                  const glm::dvec3& probe_in_mm, double probe_radius_mm,
                                  double max_penetration_mm, bool any_shadow, std::uint64_t frame) {
  SurfaceModel m = last;
  m.frame = frame;
  m.probe_radius_mm = probe_radius_mm;
  const double len = glm::length(reference_normal);
  if (!any_shadow || !(len > 0.0) || !std::isfinite(len)) { m.valid = false; return m; }
  m.normal = reference_normal / len;
  if (max_penetration_mm > 0.0 && std::isfinite(max_penetration_mm)) {
    // Lowest probe point x - R n lies max_penetration below the surface.
    m.point_mm = probe_in_mm - (probe_radius_mm - max_penetration_mm) * m.normal;
    m.valid = true;
  }
  return m;  // no penetration: keep the last plane (continuity), re-oriented to the new normal
}

}  // namespace ps
