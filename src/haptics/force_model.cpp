#include "haptics/force_model.h"

#include <cmath>

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

ForceResult compute_proxy_force(const HapticsParams& p, world::GodObject& god, const glm::dvec3& x_mm,
                                const glm::dvec3& v_mm_s, double time_s) {
  ForceResult out;
  glm::dvec3 f = external_force_n(p, time_s) - p.viscosity_n_s_per_mm * v_mm_s;
  const glm::dvec3 stick_point = god.proxy();  // last tick's proxy: where friction holds it
  const world::ProxyStep step = god.move(x_mm);
  out.proxy_mm = step.proxy_mm;
  out.facets_visited = step.facets_visited;
  const double r = glm::length(step.proxy_mm - x_mm);
  if (step.in_contact && r > 0.0) {
    const HapticsParams q = with_material(p, god.scene().material(step.surface));
    out.in_contact = true;
    out.surface = step.surface;
    out.penetration_mm = r;
    const glm::dvec3 n = q.force_shading ? step.shaded_normal : (step.proxy_mm - x_mm) / r;
    const double fn = spring_magnitude_n(q, r);
    f += fn * n;
    f -= q.damping_n_s_per_mm * glm::dot(n, v_mm_s) * n;
    glm::dvec3 held = stick_point;
    f += friction(q, step.contact_normal, fn, step.proxy_mm, held, out.sticking);
    if (held != step.proxy_mm) {
      const world::ProxyStep back = god.move(held);  // constrained: stops at any surface
      out.proxy_mm = back.proxy_mm;
      out.facets_visited += back.facets_visited;
    }
  }
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
