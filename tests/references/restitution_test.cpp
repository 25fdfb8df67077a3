// The oracles themselves against the numbers docs/theory.md reports (independent derivations).
#include <gtest/gtest.h>

#include <cmath>

#include "references/cohesion.hpp"
#include "references/free_fall.hpp"
#include "references/restitution.hpp"

using namespace references;

TEST(KelvinVoigtCollision, TheoryTable) {
  const double rows[][3] = {{0.05, 0.85447, 0.85876}, {0.2, 0.52662, 0.57174}, {0.7, 0.04599, 0.21028}};
  for (const auto& r : rows) {
    EXPECT_NEAR(kelvin_voigt_collision(1.0, 2 * r[0], 1.0, false).restitution, r[1], 1e-5);
    EXPECT_NEAR(kelvin_voigt_collision(1.0, 2 * r[0], 1.0, true).restitution, r[2], 1e-5);
  }
  EXPECT_THROW(kelvin_voigt_collision(1.0, 2.5, 1.0, false), std::domain_error);
  // Overdamped, clamped: e = ((β−Ω)/(β+Ω))^{β/Ω} > 0.
  const double b = 1.5, o = std::sqrt(b * b - 1);
  EXPECT_NEAR(kelvin_voigt_collision(1.0, 3.0, 1.0, true).restitution, std::pow((b - o) / (b + o), b / o), 1e-14);
}

TEST(RestitutionWithGravity, ReducesToTheFreeCollisionAndMatchesTheoryFactors) {
  // G = g/(ω0 v0) → 0 recovers §1a; docs/theory.md §1c: ζ = 0.1, G = 0.1 → e/e0 = 0.9478, G = 0.3 → 0.8066.
  const double e0 = kelvin_voigt_collision(1.0, 0.2, 1.0, false).restitution;
  EXPECT_NEAR(restitution_with_gravity(1.0, 0.2, 1.0, 1.0, 1e-9, false), e0, 1e-8);
  EXPECT_NEAR(restitution_with_gravity(1.0, 0.2, 1.0, 1.0, 0.1, false) / e0, 0.9478, 1e-3);
  EXPECT_NEAR(restitution_with_gravity(1.0, 0.2, 1.0, 1.0, 0.3, false) / e0, 0.8066, 1e-3);
  // Elastic with gravity: e = 1 exactly.
  EXPECT_NEAR(restitution_with_gravity(1.0, 0.0, 1.0, 1.0, 0.2, false), 1.0, 1e-9);
}

TEST(CohesionSeparation, TheoryWorkedExample) {
  // docs/theory.md §2a: ω_c = 1, |δ_c| = 0.2, ζ = 0.1 collision at v: u0 = e v, final √(u0² − 0.04).
  const double e = kelvin_voigt_collision(1.0, 0.2, 1.0, false).restitution;
  // k = 1, m_eff = 1, reach = p_N g m_min / k = 0.2 with p_N g m_min = 0.2.
  EXPECT_NEAR(cohesion_separation(1.0, 1.0, 1.0, 0.2, 1.0, e * 0.28).final_speed, 0.041150, 2e-6);
  EXPECT_NEAR(cohesion_separation(1.0, 1.0, 1.0, 0.2, 1.0, e * 1.0).final_speed, 0.701286, 2e-6);
  EXPECT_FALSE(cohesion_separation(1.0, 1.0, 1.0, 0.2, 1.0, e * 0.27).escapes);
}

TEST(FreeFall, ContactGeometryAndTime) {
  EXPECT_DOUBLE_EQ(contact_height_above(0.006, 0.010), 0.008);
  EXPECT_TRUE(std::isnan(contact_height_above(0.011, 0.010)));
  // docs/theory.md §3a check: z0 = 50 mm, R = 10 mm, b = 0: t1 = 0.090305 s.
  EXPECT_NEAR(fall_time(0.04, 9.81), 0.090305, 1e-6);
}
