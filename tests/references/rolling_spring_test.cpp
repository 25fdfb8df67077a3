// The elastic–plastic spring–dashpot rolling resistance (contact.rolling "epsd", docs/model.md
// §10.5) in whole runs against closed forms: below its limit torque a spinning ball on a floor
// rocks at Ω = √(k_r/I) with k_r = 2.25 k_n μ_r² R*², at the limit it decays as the constant
// torque does, and it holds a ball on a slope without the creep of the constant-torque model.
#include <gtest/gtest.h>

#include <cmath>

#include "friction_scenes.hpp"
#include "references/friction.hpp"

using namespace silodem_test;

namespace {

constexpr double kR = 0.005, kG = 9.81;

json epsd_grain(double mu_r, double eta_r) {
  // k_i = 2e5 N/m: the pair with the floor (the same constants) has k_n = 1e5 N/m (11).
  return {{"density", 2500}, {"stiffness", 2e5}, {"restitution", 0.5}, {"reference_radius", kR},
          {"rolling_friction", mu_r}, {"rolling_damping_ratio", eta_r}};
}

double ball_mass() { return 2500 * 4.0 / 3.0 * M_PI * kR * kR * kR; }
double r_star() { return kR * kFloorRadius / (kR + kFloorRadius); }

}  // namespace

TEST(RollingSpring, BelowItsLimitABallRocksAtTheRollingSpringsFrequency) {
  // No tangential law: the rolling torque is a pure couple, so I ω̇ = −k_r θ with I = 2/5 m r²:
  // ω = ω0 cos Ω t, Ω = √(k_r/I) = 1.04e4 rad/s. ω0 = 0.1 rad/s keeps the largest spring torque,
  // I Ω ω0 = 1.4e-5 N m, below the limit μ_r R* m g = 3.2e-5 N m. Δt = 1e-6 s (ΩΔt = 0.01): the
  // spring, loaded by the force law at first order, damps by a ratio ΩΔt/4 (theory.md §7.7),
  // 0.8 % over half a period. A prefactor other than 2.25 would move the quarter-period zero by
  // its square root: 2.0 instead of 2.25 leaves ω(T/4) at 9 % of ω0; the test allows 1.5 %.
  const double mu_r = 0.5, w0 = 0.1, k_n = 1e5;
  const double k_r = 2.25 * k_n * mu_r * mu_r * r_star() * r_star(), inertia = 0.4 * ball_mass() * kR * kR;
  const double omega = std::sqrt(k_r / inertia), period = 2.0 * M_PI / omega;
  ASSERT_LT(inertia * omega * w0, mu_r * r_star() * ball_mass() * kG);
  const auto spin_after = [&](double t, const char* name) {
    json c = on_floor(name, {{"rolling", "epsd"}}, epsd_grain(mu_r, 0.0), kR, 0.0, w0, t);
    c["time"]["dt"] = 1e-6;
    return run(c);
  };
  const json quarter = spin_after(0.25 * period, "epsd_quarter");
  EXPECT_LT(std::abs(vec(probe(quarter, "ball")["final_angular_velocity"]).y()), 0.015 * w0);
  // All of the rotation's energy is in the rolling spring then, booked as its own term.
  EXPECT_NEAR(quarter["energy"]["elastic_rolling"].get<double>(), 0.5 * inertia * w0 * w0, 0.02 * 0.5 * inertia * w0 * w0);
  const json half = spin_after(0.5 * period, "epsd_half");
  EXPECT_NEAR(vec(probe(half, "ball")["final_angular_velocity"]).y(), -w0, 0.015 * w0);
  // Translation untouched: a pure couple.
  EXPECT_LT(std::abs(vec(probe(half, "ball")["final_velocity"]).x()), 1e-12);
}

TEST(RollingSpring, AtItsLimitASpinningBallSlowsAsUnderTheConstantTorqueAndComesToRest) {
  // ω0 = 20 rad/s: the spring reaches the limit M_m = μ_r R* m g within a step and stays there,
  // so ω = ω0 − 5 μ_r g t/(2R) as for the constant torque (references::rolling_spin), to the
  // spring's elastic part, M_m/k_r = 2e-4 rad of lag. Past 0.041 s it rocks elastically and the
  // dashpot (η_r = 0.3, off at the limit) brings it to rest.
  const double mu_r = 0.1, w0 = 20.0, t1 = 0.02;
  const json a = run(on_floor("epsd_spin", {{"rolling", "epsd"}}, epsd_grain(mu_r, 0.3), kR, 0.0, w0, t1));
  EXPECT_NEAR(vec(probe(a, "ball")["final_angular_velocity"]).y(), references::rolling_spin(w0, mu_r, kG, kR, t1), 1e-3 * w0);
  const json b = run(on_floor("epsd_stop", {{"rolling", "epsd"}}, epsd_grain(mu_r, 0.3), kR, 0.0, w0, 0.06));
  EXPECT_LT(std::abs(vec(probe(b, "ball")["final_angular_velocity"]).y()), 1e-6 * w0);
}

TEST(RollingSpring, HoldsABallOnASlopeBelowItsLimitWithoutCreep) {
  // tan θ = 0.05 < μ_r = 0.1 (the torque m g sin θ r about the contact is below M_m): the spring
  // takes the load elastically, so the ball settles at a fixed small rotation and does not move
  // on. Free it would roll 5/14 g sin θ t² = 1.7 mm in 0.1 s; the constant torque's one-step
  // limiter lets it creep by up to g Δt per step (RollingResistanceHoldsABallOnASlopeBelowItsLimit);
  // the spring holds it to the elastic displacement r θ ≤ r M_m/k_r ≈ 1e-6 m.
  json grain = epsd_grain(0.1, 0.3);
  grain["friction"] = 0.5;
  grain["tangential_damping_ratio"] = 0.5;
  const double deg = std::atan(0.05) * 180.0 / M_PI;
  const json s = run(on_incline("epsd_held", {{"tangential", "linear_history"}, {"rolling", "epsd"}}, grain, kR, deg, 0.1));
  EXPECT_LT(std::abs(vec(probe(s, "ball")["final_position"]).x()), 2e-6);
  EXPECT_LT(std::abs(vec(probe(s, "ball")["final_velocity"]).x()), 1e-6);
  EXPECT_LT(std::abs(vec(probe(s, "ball")["final_angular_velocity"]).y()), 1e-3);
}

TEST(RollingSpring, TheLedgerClosesWithTheRollingSpringAndItsDashpot) {
  // Rolling with friction and the EPSD spring until rest: the friction work less what the springs
  // still hold is the dissipation, and the balance stays at the trapezoid rule's error, which at
  // t_c/100 is well under 1e-3 of the energy that moved (the ledger's tests of theory.md §8.1).
  json grain = epsd_grain(0.1, 0.3);
  grain["friction"] = 0.5;
  const json s = run(on_floor("epsd_ledger", {{"tangential", "linear_history"}, {"rolling", "epsd"}}, grain, kR, 0.3, 0.0, 0.4));
  EXPECT_LT(std::abs(s["energy"]["max_abs_relative_drift"].get<double>()), 1e-3);
  EXPECT_GT(s["energy"]["friction_dissipated"].get<double>(), 0.9 * 0.5 * ball_mass() * 0.3 * 0.3);
}
