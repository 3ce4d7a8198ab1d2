// Force suggestions (Hanson & Zhang §4.3, eq. 5): a "power assisted" push that steers the proxy
// toward where the hand is predicted to go,
//   f_pd = K_p (P_des - P) - K_v (V_des - V),
// projected on the local facet (its tangent plane: the suggestion never pushes into or out of
// the surface). P, V: the contact point and its velocity; P_des, V_des: the desired ones, from
// the Kalman filter's velocity (haptics/kalman.h) carried ahead by `lookahead_s`. The sign of
// the K_v term is Hanson & Zhang's. Units: mm, mm/s, N.
#pragma once

#include <glm/glm.hpp>

namespace ps::fourd {

struct SuggestionParams {
  double kp_n_per_mm = 0.0;     // 0 and kv 0: off
  double kv_n_s_per_mm = 0.0;
  double lookahead_s = 0.05;    // P_des = P + lookahead_s V_des
  bool operator==(const SuggestionParams&) const = default;
  bool on() const { return kp_n_per_mm > 0.0 || kv_n_s_per_mm > 0.0; }
};

// Eq. 5 projected on the plane with unit normal n: zero when P = P_des and V = V_des.
glm::dvec3 force_suggestion_n(const SuggestionParams& p, const glm::dvec3& p_des_mm, const glm::dvec3& p_mm,
                              const glm::dvec3& v_des_mm_s, const glm::dvec3& v_mm_s, const glm::dvec3& n);

// The desired state from the filtered hand velocity: V_des = the velocity's tangential part,
// P_des = P + lookahead_s V_des.
void desired_state(const SuggestionParams& p, const glm::dvec3& p_mm, const glm::dvec3& hand_v_mm_s,
                   const glm::dvec3& n, glm::dvec3& p_des_mm, glm::dvec3& v_des_mm_s);

}  // namespace ps::fourd
