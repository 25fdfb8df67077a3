// Stop tests (27)–(29) and the kinetic test on hand-made accelerations and energies.
#include <gtest/gtest.h>

#include "silodem/stop/equilibrium.hpp"

using namespace silodem;

namespace {
Particles two_balls_and_a_wall() {
  Particles p;
  p.add({Vec3::Zero(), Vec3::Zero(), 0.01, 1.0, 1, 0, 0, "a"}, false);
  p.add({Vec3::Zero(), Vec3::Zero(), 0.01, 2.0, 1, 0, 0, "b"}, false);
  p.add({Vec3::Zero(), Vec3::Zero(), 0.01, 50.0, 1, 0, 0, "wall"}, true);  // walls do not count
  return p;
}
}  // namespace

TEST(Equilibrium, LocalAndGlobalThresholds) {
  const Particles p = two_balls_and_a_wall();
  EquilibriumSpec spec;  // p_f = 0.1, p_ft = 0.01
  const double g = 10.0;
  // Unbalanced forces m a: (0.5, 0, 0) and (0, 0, −0.2): f_max = 0.5, |Σ| = √(0.25 + 0.04).
  const auto m = measure_equilibrium(p, {Vec3(0.5, 0, 0), Vec3(0, 0, -0.1)}, g, spec, 0.0, 1.0);
  EXPECT_DOUBLE_EQ(m.f_max, 0.5);
  EXPECT_NEAR(m.f_total, std::sqrt(0.29), 1e-15);  // (28) as the Euclidean norm of the sum
  EXPECT_DOUBLE_EQ(m.eps_f, 0.1 * g * 1.0);         // smallest ball's weight
  EXPECT_DOUBLE_EQ(m.eps_ft, 0.01 * g * 3.0);       // (29)
  EXPECT_TRUE(m.local_ok());
  EXPECT_FALSE(m.global_ok());
  EXPECT_FALSE(m.at_rest());  // both must hold
  EXPECT_TRUE(measure_equilibrium(p, {Vec3(0.1, 0, 0), Vec3(-0.1, 0, 0)}, g, spec, 0.0, 1.0).at_rest());
}

TEST(Equilibrium, KineticTestMustHoldWithTheForceTestsUnlessPaperLiteral) {
  const Particles p = two_balls_and_a_wall();
  EquilibriumSpec spec;  // forces_and_kinetic, p_k = 1e-3
  const std::vector<Vec3> balanced{Vec3::Zero(), Vec3::Zero()};
  // Forces balanced, but half the contact energy is still motion: not at rest.
  const auto swinging = measure_equilibrium(p, balanced, 10.0, spec, 0.5, 1.0);
  EXPECT_TRUE(swinging.local_ok() && swinging.global_ok());
  EXPECT_DOUBLE_EQ(swinging.eps_k, 1e-3);
  EXPECT_FALSE(swinging.kinetic_ok());
  EXPECT_FALSE(swinging.at_rest());
  // Just under and just over p_k E_el.
  EXPECT_TRUE(measure_equilibrium(p, balanced, 10.0, spec, 0.999e-3, 1.0).at_rest());
  EXPECT_FALSE(measure_equilibrium(p, balanced, 10.0, spec, 1.001e-3, 1.0).at_rest());
  // No contact energy (in flight): the kinetic test cannot hold.
  EXPECT_FALSE(measure_equilibrium(p, balanced, 10.0, spec, 0.0, 0.0).kinetic_ok());
  // The kinetic test never rescues an unbalanced state.
  EXPECT_FALSE(measure_equilibrium(p, {Vec3(5.0, 0, 0), Vec3::Zero()}, 10.0, spec, 0.0, 1.0).at_rest());
  spec.test = EquilibriumTest::PaperLiteral;  // (27)–(29) alone
  EXPECT_TRUE(measure_equilibrium(p, balanced, 10.0, spec, 0.5, 1.0).at_rest());
}
