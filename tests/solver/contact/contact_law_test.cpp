// The interaction law (4), (9), (10) against hand-computed numbers.
#include <gtest/gtest.h>

#include "silodem/contact/contact_law.hpp"
#include "silodem/contact/pair_constants.hpp"

using namespace silodem::contact;

TEST(Overlap, IsSumOfRadiiMinusDistance) {  // (5)
  EXPECT_DOUBLE_EQ(overlap(0.005, 0.003, 0.0075), 0.0005);
  EXPECT_LT(overlap(0.005, 0.003, 0.009), 0.0);
}

TEST(KelvinVoigt, SpringPlusDashpotOpposingApproach) {
  // k = 1e5 N/m, c = 3 N s/m, δ = 1e-5 m approaching at 0.2 m/s: f = 1 + 0.6 N, repulsive.
  const PairForce a = kelvin_voigt<false>(1e5, 3.0, 1e-5, 0.2);
  EXPECT_NEAR(a.f, 1.6, 1e-12);
  EXPECT_NEAR(a.elastic, 0.5 * 1e5 * 1e-10, 1e-18);
  EXPECT_NEAR(a.p_dissipated, 3.0 * 0.04, 1e-12);
  // Separating at 0.5 m/s with a small overlap: the paper's unclamped law pulls (tensile).
  const PairForce b = kelvin_voigt<false>(1e5, 3.0, 1e-6, -0.5);
  EXPECT_NEAR(b.f, 0.1 - 1.5, 1e-12);
  EXPECT_NEAR(b.p_dissipated, 0.75, 1e-12);
}

TEST(KelvinVoigt, ClampRemovesTensionAndBooksTheSpringLoss) {
  const PairForce b = kelvin_voigt<true>(1e5, 3.0, 1e-6, -0.5);
  EXPECT_EQ(b.f, 0.0);
  // With no force, the spring energy released as δ shrinks is lost: −k δ δ̇ = 1e5·1e-6·0.5.
  EXPECT_NEAR(b.p_dissipated, 0.05, 1e-12);
  // A compressive force is left alone.
  EXPECT_NEAR(kelvin_voigt<true>(1e5, 3.0, 1e-5, 0.2).f, 1.6, 1e-12);
}

TEST(Cohesion, PullsOnlyWhileSeparatingInsideTheReach) {
  const double k = 1e5, dc = -2e-8;
  const PairForce sep = cohesion(k, dc, -1e-8, -1e-3);
  EXPECT_NEAR(sep.f, -1e-3, 1e-15);  // k δ, tensile
  EXPECT_NEAR(sep.elastic, 0.5 * k * 1e-16, 1e-24);
  EXPECT_NEAR(sep.p_cohesion, k * 1e-8 * 1e-3, 1e-15);
  EXPECT_EQ(cohesion(k, dc, -1e-8, +1e-3).f, 0.0);   // approaching: no force
  EXPECT_EQ(cohesion(k, dc, -1e-8, 0.0).f, 0.0);     // tangential motion: no force
  EXPECT_EQ(cohesion(k, dc, -3e-8, -1e-3).f, 0.0);   // beyond the reach
}

TEST(Cohesion, ReachIsTenPercentOfTheLighterWeight) {  // (10)
  // m_min = 1e-3 kg, g = 9.81, p_N = 0.1, k_ij = 1e4: δ_c = −9.81e-4/1e4.
  EXPECT_NEAR(cohesion_reach(0.1, 9.81, 1e-3, 1e4), -9.81e-8, 1e-20);
}
