// Force models of the haptic loop (docs/haptics.md has the equations and defaults).
// Units: mm, mm/s, s, newtons (N). The device is a sphere of the probe's radius; the surface is
// the render thread's local model: a plane (normal n, point p0) around the last contact,
// "local model by continuity" (Hanson & Zhang §4.2), updated once per rendered frame.
//   penetration   r = R - n.(x - p0)                     (mm, > 0 in contact)
//   spring        f_n = alpha r^(1+beta) n               (sticky stylus, 000 eq. 1)
//   damping       f_d = -K_d (n.v) n                     (radial velocity, 000 eq. 2)
//   viscosity     f_v = -b v                             (Sepulveda-Cervantes et al., room 2)
//   friction      tangent part through Q = I - n n^T: a proxy sticks while
//                 |k_t Q(proxy - x)| <= mu_s |f_n| and slides at |f_t| = mu_d |f_n|
//   external      f_e = F0 + F1 sin(2 pi f t)            (Sepulveda-Cervantes et al., room 5)
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "scene/haptic_material.h"

namespace ps {

namespace world { class GodObject; }

// Kept out of the scene format on purpose: these are device-side tuning values, not the look
// of a surface; the defaults suit a desktop 3-DOF device (Falcon-class, ~9 N peak).
struct HapticsParams {
  double stiffness_n_per_mm = 0.5;          // alpha (beta = 0: 500 N/m linear spring)
  double stiffness_exponent = 0.0;          // beta (0 = ideal linear spring)
  double damping_n_s_per_mm = 0.002;        // K_d on the normal velocity (2 N s/m)
  double viscosity_n_s_per_mm = 0.0;        // b, everywhere (0 = no medium)
  double static_friction = 0.3;             // mu_s, unitless
  double dynamic_friction = 0.2;            // mu_d <= mu_s
  double tangent_stiffness_n_per_mm = 0.5;  // k_t of the stick spring
  glm::dvec3 external_force_n{0.0};         // F0, constant
  glm::dvec3 external_fluctuation_n{0.0};   // F1, amplitude of the sinusoidal part
  double external_frequency_hz = 1.0;       // f
  double max_force_n = 8.0;                 // magnitude clamp (device safety)
  // Haptic scene contacts: the normal force follows the interpolated vertex normal at the
  // contact (A Virtual Universe §6) instead of the god-object's own direction (proxy - device).
  bool force_shading = true;
  // Virtual coupling of device and proxy (docs/haptics.md, "Pseudo-haptic coupling"): a force
  // F on the probe from the scene's fields and bodies moves the god-object's goal to
  // device + F / coupling, so the drawn proxy lags, deflects and is pulled by what acts on it.
  double coupling_n_per_mm = 0.5;
};

// The loop's values with the touched surface's feel (stiffness, exponent, damping, friction).
HapticsParams with_material(const HapticsParams& p, const HapticMaterial& m);

// Published by the render thread, read by the haptic thread (Snapshot<SurfaceModel>).
struct SurfaceModel {
  bool valid = false;           // false: free space, no contact possible
  glm::dvec3 normal{0.0, 0.0, 1.0};
  glm::dvec3 point_mm{0.0};     // a point on the local surface plane
  double probe_radius_mm = 0.0; // R
  std::uint64_t frame = 0;      // render frame that produced it
};

struct ForceResult {
  glm::dvec3 force_n{0.0};  // on the user's hand
  glm::dvec3 proxy_mm{0.0}; // constrained probe position shown by the renderer
  double penetration_mm = 0.0;
  bool in_contact = false;
  bool sticking = false;
  bool catching_up = false;         // the proxy free but short of the goal (world::ProxyStep::short_of_goal)
  int surface = -1;                 // haptic scene: the surface touched (Scene::surfaces index)
  glm::dvec3 contact_normal{0.0, 0.0, 1.0};  // in contact: unit, out of the surface (contact point -> proxy)
  int medium = -1;                  // haptic scene: the penetrable volume holding the proxy centre
  std::uint32_t facets_visited = 0; // haptic scene: mesh triangles examined this tick
};

glm::dmat3 normal_projector(const glm::dvec3& n);   // P = n n^T
glm::dmat3 tangent_projector(const glm::dvec3& n);  // Q = I - n n^T

double spring_magnitude_n(const HapticsParams& p, double penetration_mm);
glm::dvec3 external_force_n(const HapticsParams& p, double time_s);

// One tick: device position x and (filtered) velocity v, the previous proxy, session time.
ForceResult compute_force(const HapticsParams& p, const SurfaceModel& m, const glm::dvec3& x_mm,
                          const glm::dvec3& v_mm_s, const glm::dvec3& prev_proxy_mm, double time_s);

// One tick against the haptic scene (docs/haptics.md, "Haptic geometry"): the god-object moves
// toward the device x; in contact, with r = |proxy - x| and n the contact normal (force-shaded
// when p.force_shading, else (proxy - x) / r), the touched material's spring and damping act
// along n, and the stick/slide friction above acts on the proxy's contact plane: the stick
// point is the previous proxy, the frictionless god-object position plays x_surface, and the
// proxy is moved (never through a surface) to where friction leaves it.
// The touched material's texture (along n, at most cancelling the push) and stickiness act at
// the contact; out of contact a magnetic surface within its range pulls (material_forces.h),
// and with the proxy centre inside a penetrable volume (HapticScene::medium_at) its -b v acts.
ForceResult compute_proxy_force(const HapticsParams& p, world::GodObject& god, const glm::dvec3& x_mm,
                                const glm::dvec3& v_mm_s, double time_s,
                                const glm::dvec3& field_force_n = glm::dvec3(0.0));

// Render-side update of the local model from one frame: probe_in_mm is the position given to
// the renderer, max_penetration_mm and reference_normal come from its FrameStats; no shadow
// pixels means the probe is far from every surface, so the model is dropped.
SurfaceModel update_surface_model(const SurfaceModel& last, const glm::dvec3& reference_normal,
                                  const glm::dvec3& probe_in_mm, double probe_radius_mm,
                                  double max_penetration_mm, bool any_shadow, std::uint64_t frame);

}  // namespace ps
