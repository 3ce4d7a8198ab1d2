#include "fourd/suggestion.h"

namespace ps::fourd {
namespace {
glm::dvec3 tangential(const glm::dvec3& v, const glm::dvec3& n) { return v - glm::dot(v, n) * n; }
}  // namespace

glm::dvec3 force_suggestion_n(const SuggestionParams& p, const glm::dvec3& p_des_mm, const glm::dvec3& p_mm,
                              const glm::dvec3& v_des_mm_s, const glm::dvec3& v_mm_s, const glm::dvec3& n) {
  const glm::dvec3 f = p.kp_n_per_mm * (p_des_mm - p_mm) - p.kv_n_s_per_mm * (v_des_mm_s - v_mm_s);
  return tangential(f, n);
}

void desired_state(const SuggestionParams& p, const glm::dvec3& p_mm, const glm::dvec3& hand_v_mm_s,
                   const glm::dvec3& n, glm::dvec3& p_des_mm, glm::dvec3& v_des_mm_s) {
  v_des_mm_s = tangential(hand_v_mm_s, n);
  p_des_mm = p_mm + p.lookahead_s * v_des_mm_s;
}

}  // namespace ps::fourd
