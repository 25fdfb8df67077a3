// Series constants (11), effective mass, and the (t_c, e) ↔ (k, c) derivation against the
// closed-form table of docs/theory.md §1b.
#include <gtest/gtest.h>

#include <cmath>

#include "silodem/contact/pair_constants.hpp"

using namespace silodem::contact;

TEST(Series, CombinesLikeSpringsInSeries) {  // (11)
  EXPECT_DOUBLE_EQ(series(2e5, 2e5), 1e5);
  EXPECT_NEAR(series(2e5, 1e5), 2e10 / 3e5, 1e-6);
  EXPECT_EQ(series(6.0, 0.0), 0.0);  // a dashpot-free ball gives a dashpot-free pair
}

TEST(EffectiveMass, WallBallHasInfiniteMass) {
  EXPECT_DOUBLE_EQ(effective_mass(2.0, 2.0, false, false), 1.0);
  EXPECT_DOUBLE_EQ(effective_mass(2.0, 5.0, false, true), 2.0);
  EXPECT_DOUBLE_EQ(effective_mass(5.0, 2.0, true, false), 2.0);
}

TEST(ContactBehaviour, MatchesTheoryTable) {
  // docs/theory.md §1b table, ω0 = 1: (ζ, e unclamped, ω0 t_c unclamped, e clamped, ω0 t* clamped).
  const double rows[][5] = {{0.10, 0.72925, 3.1574, 0.74408, 2.9561},
                            {0.30, 0.37233, 3.2933, 0.45098, 2.6545},
                            {0.50, 0.16303, 3.6276, 0.29844, 2.4184},
                            {0.70, 0.04599, 4.3991, 0.21028, 2.2276}};
  for (const auto& r : rows) {
    const double c = 2.0 * r[0];  // k = m = 1
    const auto u = contact_behaviour(1.0, c, 1.0, false);
    const auto cl = contact_behaviour(1.0, c, 1.0, true);
    EXPECT_NEAR(u.restitution, r[1], 1e-5) << r[0];
    EXPECT_NEAR(u.duration, r[2], 1e-4) << r[0];
    EXPECT_NEAR(cl.restitution, r[3], 1e-5) << r[0];
    EXPECT_NEAR(cl.duration, r[4], 1e-4) << r[0];
  }
  EXPECT_NEAR(contact_behaviour(1.0, 2.0, 1.0, true).restitution, std::exp(-2.0), 1e-12);  // critical
}

TEST(ContactBehaviour, ReferenceCodesTestPair) {
  // the test pair of docs/reference-codes.md: k = 1e5, c = 3, m_eff = 6.544985e-4 → e = 0.552796, t_c = 2.586429e-4 s,
  // clamped e = 0.593205 (measured identically in LAMMPS, YADE and LIGGGHTS).
  const auto u = contact_behaviour(1e5, 3.0, 6.544985e-4, false);
  EXPECT_NEAR(u.restitution, 0.552796, 2e-6);
  EXPECT_NEAR(u.duration, 2.586429e-4, 1e-9);
  // The codes ran at Ω = 1.2e-3, so their value carries the O(ζΩ) onset error (3ζΩ = 7e-4).
  EXPECT_NEAR(contact_behaviour(1e5, 3.0, 6.544985e-4, true).restitution, 0.593205, 7e-4);
}

TEST(Derivation, RestitutionRoundTripsForBothContactEnds) {
  for (bool clamp : {false, true})
    for (double e : {0.9, 0.7, 0.5, 0.2, 0.05}) {
      const double z = damping_ratio_for_restitution(e, clamp);
      EXPECT_NEAR(contact_behaviour(1.0, 2.0 * z, 1.0, clamp).restitution, e, 1e-10) << e << clamp;
    }
  // docs/theory.md §1b: e = 0.9 → ζ = 0.0335, e = 0.5 → 0.2155 (unclamped).
  EXPECT_NEAR(damping_ratio_for_restitution(0.9, false), 0.0335, 1e-4);
  EXPECT_NEAR(damping_ratio_for_restitution(0.5, false), 0.2155, 1e-4);
}

TEST(Derivation, BallConstantsGiveTheRequestedPairBehaviour) {
  const double m_ref = 1.308997e-3, tc = 2.5e-4, zeta = 0.2;
  const double k_pair = pair_stiffness_for_duration(tc, zeta, 0.5 * m_ref, false);
  const auto bc = ball_constants_from_pair(k_pair, zeta, m_ref);
  const auto b = contact_behaviour(series(bc.k, bc.k), series(bc.c, bc.c), 0.5 * m_ref, false);
  EXPECT_NEAR(b.duration, tc, 1e-15);
  EXPECT_NEAR(b.zeta, zeta, 1e-12);
}
