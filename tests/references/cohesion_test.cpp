// The cohesion check's scheme bounds (references/cohesion.hpp) against a pair integrated here by
// velocity Verlet, independently of the solver: in units k = m_eff = |δ_c| = 1 (ω_c = v* = 1) the
// separating pair feels −s while 0 ≤ s ≤ 1 and it opens, nothing otherwise. Over a sweep of step
// sizes every error stays within its bound, and the largest comes within a factor of a few of it
// (the first-order edge effect the bound is made of is really there).
#include <gtest/gtest.h>

#include <cmath>

#include "references/cohesion.hpp"

namespace {

struct Outcome {
  double max_gap;     // largest sampled gap (captured pair)
  double final_speed; // after leaving the zone (escaping pair)
  double gap_at_exit; // the first sample beyond the edge, where the spring lets go
};

Outcome integrate(double u0, double dt) {
  const auto accel = [](double s, double u) { return s >= 0.0 && s <= 1.0 && u > 0.0 ? -s : 0.0; };
  double s = 0.0, u = u0, a = accel(s, u);
  Outcome o{0.0, 0.0, NAN};
  for (long n = 0; n < 100000000L; ++n) {
    const double half = u + 0.5 * dt * a;
    s += dt * half;
    a = accel(s, half);
    u = half + 0.5 * dt * a;
    o.max_gap = std::max(o.max_gap, s);
    if (u < 0.0) break;  // turned: captured
    if (s > 1.0 && std::isnan(o.gap_at_exit)) o.gap_at_exit = s;
    if (s > 2.0) break;  // far out: escaped
  }
  o.final_speed = u;
  return o;
}

}  // namespace

TEST(CohesionBounds, EscapeSpeedWithinTheBoundOverASweepOfSteps) {
  const auto th = references::cohesion_separation(1.0, 1.0, 1.0, 1.0, 1.0, 1.05);  // u0 = 1.05 v*
  ASSERT_TRUE(th.escapes);
  EXPECT_NEAR(th.final_speed, std::sqrt(1.05 * 1.05 - 1.0), 1e-15);
  double worst_ratio = 0.0;
  for (int i = 0; i < 40; ++i) {
    const double omega_dt = 0.01 + 0.0023 * i;
    const Outcome o = integrate(1.05, omega_dt);
    const double err = std::abs(o.final_speed / th.final_speed - 1.0);
    const double bound = references::escape_speed_bound(th, omega_dt);
    EXPECT_LE(err, bound) << "Omega = " << omega_dt;
    worst_ratio = std::max(worst_ratio, err / bound);
  }
  EXPECT_GT(worst_ratio, 0.2) << "the bound is far looser than the edge effect it describes";
}

TEST(CohesionBounds, TurningGapAndEnergyWithinTheirBounds) {
  const auto captured = references::cohesion_separation(1.0, 1.0, 1.0, 1.0, 1.0, 0.95);
  const auto escaping = references::cohesion_separation(1.0, 1.0, 1.0, 1.0, 1.0, 1.05);
  ASSERT_FALSE(captured.escapes);
  EXPECT_NEAR(captured.turning_gap, 0.95, 1e-15);
  for (int i = 0; i < 40; ++i) {
    const double omega_dt = 0.01 + 0.0023 * i;
    const Outcome c = integrate(0.95, omega_dt);
    EXPECT_LE(std::abs(c.max_gap / captured.turning_gap - 1.0), references::turning_gap_bound(captured, omega_dt, 1.0))
        << "Omega = " << omega_dt;
    // Captured: the spring lets go at the turn holding ½ s_max², against ½ m_eff u0².
    EXPECT_LE(std::abs(c.max_gap * c.max_gap / (0.95 * 0.95) - 1.0),
              references::cohesion_energy_bound(captured, omega_dt, 1.0))
        << "Omega = " << omega_dt;
    // Escaping: it lets go at the first sample past the edge, holding ½ s², against ½ k δ_c².
    const Outcome e = integrate(1.05, omega_dt);
    EXPECT_LE(std::abs(e.gap_at_exit * e.gap_at_exit - 1.0), references::cohesion_energy_bound(escaping, omega_dt, 1.0))
        << "Omega = " << omega_dt;
  }
}
