// Stop tests (27)–(29) on hand-made accelerations.
#include <gtest/gtest.h>

#include "silodem/stop/equilibrium.hpp"

using namespace silodem;

TEST(Equilibrium, LocalAndGlobalThresholds) {
  Particles p;
  p.add({Vec3::Zero(), Vec3::Zero(), 0.01, 1.0, 1, 0, 0, "a"}, false);
  p.add({Vec3::Zero(), Vec3::Zero(), 0.01, 2.0, 1, 0, 0, "b"}, false);
  p.add({Vec3::Zero(), Vec3::Zero(), 0.01, 50.0, 1, 0, 0, "wall"}, true);  // walls do not count
  EquilibriumSpec spec;  // p_f = 0.1, p_ft = 0.01
  const double g = 10.0;
  // Unbalanced forces m a: (0.5, 0, 0) and (0, 0, −0.2): f_max = 0.5, |Σ| = √(0.25 + 0.04).
  const auto m = measure_equilibrium(p, {Vec3(0.5, 0, 0), Vec3(0, 0, -0.1)}, g, spec);
  EXPECT_DOUBLE_EQ(m.f_max, 0.5);
  EXPECT_NEAR(m.f_total, std::sqrt(0.29), 1e-15);  // (28) as the Euclidean norm of the sum
  EXPECT_DOUBLE_EQ(m.eps_f, 0.1 * g * 1.0);         // smallest ball's weight
  EXPECT_DOUBLE_EQ(m.eps_ft, 0.01 * g * 3.0);       // (29)
  EXPECT_TRUE(m.local_ok());
  EXPECT_FALSE(m.global_ok());
  EXPECT_FALSE(m.at_rest());  // both must hold
  EXPECT_TRUE(measure_equilibrium(p, {Vec3(0.1, 0, 0), Vec3(-0.1, 0, 0)}, g, spec).at_rest());
}
