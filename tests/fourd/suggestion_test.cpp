// Force suggestions (Hanson & Zhang §4.3, eq. 5) against their definition. No GL.
#include <gtest/gtest.h>

#include "fourd/suggestion.h"

namespace ps::fourd {
namespace {

// f = K_p (P_des - P) - K_v (V_des - V), tangential: exactly zero at P = P_des, V = V_des
// (whatever the gains), tangent to the facet always (1e-12: one projection in double), and the
// K_p term points from P toward P_des.
TEST(FourdSuggestionTest, VanishesAtTheDesiredStateAndStaysOnTheFacet) {
  const SuggestionParams p{0.5, 0.02, 0.05};
  const glm::dvec3 n = glm::normalize(glm::dvec3(0.2, -0.3, 1.0));
  const glm::dvec3 pos(3, 4, 5), vel(10, -20, 5);
  EXPECT_EQ(force_suggestion_n(p, pos, pos, vel, vel, n), glm::dvec3(0.0));
  const glm::dvec3 f = force_suggestion_n(p, pos + glm::dvec3(2, 1, 7), pos, glm::dvec3(30, 0, -4), vel, n);
  EXPECT_NEAR(glm::dot(f, n), 0.0, 1e-12);
  const SuggestionParams kp_only{0.5, 0.0, 0.05};
  const glm::dvec3 ahead = pos + glm::dvec3(1, 0, 0);
  EXPECT_GT(glm::dot(force_suggestion_n(kp_only, ahead, pos, vel, vel, n), ahead - pos), 0.0);
  // The desired state from the hand: V_des is the hand's velocity along the facet, P_des ahead by
  // lookahead_s V_des; so f = K_p lookahead_s V_des - K_v (V_des - V).
  glm::dvec3 p_des, v_des;
  desired_state(p, pos, vel, n, p_des, v_des);
  EXPECT_NEAR(glm::dot(v_des, n), 0.0, 1e-12);
  const glm::dvec3 g = force_suggestion_n(p, p_des, pos, v_des, v_des, n);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(g[i], p.kp_n_per_mm * p.lookahead_s * v_des[i], 1e-12);
  EXPECT_FALSE(SuggestionParams{}.on());
}

}  // namespace
}  // namespace ps::fourd
