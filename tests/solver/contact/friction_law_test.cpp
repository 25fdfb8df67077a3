// The friction, rolling and Hertz sub-models (docs/model.md §10) alone, against closed forms and
// hand-computed numbers.
#include <gtest/gtest.h>

#include <cmath>

#include "silodem/contact/contact_model.hpp"
#include "silodem/contact/hertz.hpp"
#include "silodem/contact/hertz_constants.hpp"
#include "silodem/contact/rolling.hpp"
#include "silodem/contact/tangential.hpp"

using namespace silodem;
using namespace silodem::contact;

TEST(SlipVelocity, VanishesForABallRollingWithoutSlipOnAFloor) {
  // Ball i above a fixed floor ball j: n = +z. Rolling in +x at u needs ω = (0, u/a, 0).
  const double u = 0.7, arm = 0.01;
  const Vec3 n(0, 0, 1), v(u, 0, 0), w(0, u / arm, 0);
  EXPECT_LT(slip_velocity(v, w, Vec3::Zero(), arm, arm, n).norm(), 1e-15);
  // Spinning the other way doubles the slip; the normal part is never in the slip.
  EXPECT_NEAR(slip_velocity(v, -w, Vec3::Zero(), arm, arm, n).x(), 2 * u, 1e-14);
  EXPECT_EQ(slip_velocity(Vec3(0, 0, -3), Vec3::Zero(), Vec3::Zero(), arm, arm, n).norm(), 0.0);
}

TEST(SlipVelocity, EqualAndOppositeSpinsOfTwoEqualBallsCancelAtTheContact) {
  // Chung & Ooi test 7: spins arranged so that the contact points move together.
  const Vec3 n(1, 0, 0), w(0, 0, 5.0);
  EXPECT_LT(slip_velocity(Vec3(-0.4, 0, 0), w, -w, 0.1, 0.1, n).norm(), 1e-15);
}

TEST(CoulombSliding, IsViscousBelowTheCapAndCoulombAbove) {
  const Vec3 vt(0.3, -0.4, 0);  // |v_t| = 0.5
  const TangentialForce slow = coulomb_sliding(vt, 2.0, 0.5, 10.0);  // γ|v| = 1 < μF = 5
  EXPECT_NEAR((slow.force + 2.0 * vt).norm(), 0.0, 1e-15);
  EXPECT_FALSE(slow.sliding);
  const TangentialForce fast = coulomb_sliding(vt, 200.0, 0.5, 10.0);
  EXPECT_NEAR(fast.force.norm(), 5.0, 1e-14);
  EXPECT_NEAR(fast.force.normalized().dot(vt.normalized()), -1.0, 1e-15);
  EXPECT_TRUE(fast.sliding);
  EXPECT_EQ(coulomb_sliding(vt, 200.0, 0.5, -3.0).force.norm(), 0.0);  // tension: no friction
}

TEST(HistorySpring, SticksBelowTheCapAndSlidesAtItWithTheSpringReset) {
  const double kt = 1e4, dt = 1e-4, mu = 0.3, fn = 2.0;
  // One step at 0.1 m/s: ξ = 1e-5 m, F = −0.1 N, well below μF_n = 0.6 N.
  const TangentialForce a = history_spring(Vec3::Zero(), Vec3(0.1, 0, 0), dt, kt, 0.0, mu, fn);
  EXPECT_NEAR(a.force.x(), -0.1, 1e-15);
  EXPECT_NEAR(a.spring.x(), 1e-5, 1e-20);
  EXPECT_NEAR(a.elastic, 0.5 * kt * 1e-10, 1e-20);
  EXPECT_FALSE(a.sliding);
  // A spring of 1e-4 m (1 N) is past the cap: the force is μF_n and the spring holds just that.
  const TangentialForce b = history_spring(Vec3(1e-4, 0, 0), Vec3::Zero(), dt, kt, 0.0, mu, fn);
  EXPECT_TRUE(b.sliding);
  EXPECT_NEAR(b.force.x(), -0.6, 1e-15);
  EXPECT_NEAR(b.spring.x(), 0.6 / kt, 1e-18);
  // With a tangential dashpot the capped force still is μF_n, and the spring is its elastic part.
  const TangentialForce c = history_spring(Vec3(1e-4, 0, 0), Vec3(0.2, 0, 0), dt, kt, 5.0, mu, fn);
  EXPECT_NEAR(c.force.norm(), 0.6, 1e-14);
  EXPECT_NEAR(-kt * c.spring.x() - 5.0 * 0.2, c.force.x(), 1e-12);
}

TEST(HistorySpring, TurnsIntoTheNewTangentPlaneKeepingItsLength) {
  const Vec3 spring(3e-6, 0, 1e-6), n = Vec3(0.1, 0, 1).normalized();
  const Vec3 turned = spring_in_tangent_plane(spring, n);
  EXPECT_NEAR(turned.dot(n), 0.0, 1e-21);
  EXPECT_NEAR(turned.norm(), spring.norm(), 1e-21);
  EXPECT_EQ(spring_in_tangent_plane(Vec3(0, 0, 2e-6), Vec3(0, 0, 1)).norm(), 0.0);  // all normal: nothing left
}

TEST(MindlinStiffness, IsEightGStarTimesTheContactRadius) {
  EXPECT_NEAR(mindlin_stiffness(2e10, 0.005, 1e-6), 8 * 2e10 * std::sqrt(5e-9), 1e-3);
}

TEST(Hertz, ForceEnergyAndModuliFollowTheClosedForms) {
  // Glass, Chung & Ooi test 1: E* = E/(2(1−ν²)) for two equal spheres.
  const double e_star = effective_modulus(48e9, 0.2, 48e9, 0.2);
  EXPECT_NEAR(e_star, 48e9 / (2 * 0.96), 1.0);
  EXPECT_NEAR(effective_shear_modulus(48e9, 0.2, 48e9, 0.2), 1.0 / (4 * 1.8 * 1.2 / 48e9), 1.0);
  const double r_star = effective_radius(0.01, 0.01), delta = 1e-4;
  const PairForce f = hertz<false>(e_star, r_star, 0.0, 1.0, delta, 0.3);
  EXPECT_NEAR(f.f, 4.0 / 3.0 * e_star * std::sqrt(r_star) * std::pow(delta, 1.5), 1e-6 * f.f);
  // Elastic energy: the integral of the force over the overlap (Simpson, 2000 panels).
  double integral = 0.0;
  const int n = 2000;
  for (int k = 0; k <= n; ++k) {
    const double d = delta * k / n, w = (k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2);
    integral += w * hertz<false>(e_star, r_star, 0.0, 1.0, d, 0.0).f;
  }
  integral *= delta / (3 * n);
  EXPECT_NEAR(f.elastic, integral, 1e-6 * integral);
  // The dashpot: c = 2ζ√(m* 2E*√(R*δ)); clamped, no tension.
  const double c = 2 * 0.1 * std::sqrt(0.5 * 2 * e_star * std::sqrt(r_star * delta));
  EXPECT_NEAR(hertz<false>(e_star, r_star, 0.1, 0.5, delta, 0.3).f, f.f + 0.3 * c, 1e-9 * f.f);
  EXPECT_EQ(hertz<true>(e_star, r_star, 0.1, 0.5, delta, -1e3).f, 0.0);
}

TEST(HertzRestitution, IsOneUndampedFallsWithDampingAndInvertsItself) {
  EXPECT_NEAR(hertz_restitution(0.0, false), 1.0, 1e-6);
  double last = 1.0;
  for (double z : {0.05, 0.1, 0.2, 0.4}) {
    const double e = hertz_restitution(z, false);
    EXPECT_LT(e, last);
    last = e;
  }
  for (double e : {0.2, 0.5, 0.9}) {
    EXPECT_NEAR(hertz_restitution(hertz_damping_ratio_for_restitution(e, false), false), e, 1e-8);
    EXPECT_NEAR(hertz_restitution(hertz_damping_ratio_for_restitution(e, true), true), e, 1e-8);
  }
  // Clamped, the dashpot never pulls the parting balls back, so it takes more damping for one e.
  EXPECT_GT(hertz_damping_ratio_for_restitution(0.5, true), hertz_damping_ratio_for_restitution(0.5, false));
}

TEST(HertzContactTime, MatchesChungAndOoiTest1) {
  // Two glass spheres R = 10 mm at ±10 m/s: t_c = 40.3 µs (the notes' oracle, three figures).
  const double m = 2800 * 4.0 / 3.0 * M_PI * 1e-6;
  const double tc = hertz_contact_time(0.5 * m, 0.005, 48e9 / (2 * 0.96), 20.0);
  EXPECT_NEAR(tc, 40.3e-6, 0.06e-6);
}

TEST(RollingTorque, OpposesRollingStopsWithinAStepAndIgnoresTwist) {
  const Vec3 n(0, 0, 1);
  const RollingTorque a = constant_rolling_torque(Vec3(0, 10, 0), n, 0.1, 0.01, 2.0, 1e-6, 1e-5);
  EXPECT_NEAR(a.torque.y(), -0.1 * 0.01 * 2.0, 1e-15);
  EXPECT_NEAR(a.power, 0.002 * 10, 1e-15);
  // Nearly stopped: only what brings ω_r to zero in this step, I*|ω_r|/Δt.
  const RollingTorque b = constant_rolling_torque(Vec3(0, 1e-3, 0), n, 0.1, 0.01, 2.0, 1e-6, 1e-5);
  EXPECT_NEAR(b.torque.y(), -1e-6 * 1e-3 / 1e-5, 1e-15);
  EXPECT_EQ(constant_rolling_torque(Vec3(0, 0, 7), n, 0.1, 0.01, 2.0, 1e-6, 1e-5).torque.norm(), 0.0);
}

TEST(FrictionLaw, TheRollingSpringIsElasticBelowItsLimitAndPlasticWithoutDashpotAtIt) {
  // EPSD (rolling.hpp): θ ← θ + ω_r Δt, M = −k_r θ − C_r ω_r below μ_r R* F_n; at the limit the
  // torque is the limit along −θ, the spring is reset to it and the dashpot is off.
  const Vec3 n(0, 0, 1);
  const double k_r = 2.0, c_r = 0.01, mu_r = 0.1, r_star = 0.01, f_n = 2.0, dt = 1e-3;  // M_m = 2e-3 N m
  const RollingSpring a = rolling_spring(Vec3(1e-4, 0, 0), Vec3(0.1, 0, 5.0), n, k_r, c_r, mu_r, r_star, f_n, dt);
  EXPECT_FALSE(a.plastic);
  EXPECT_NEAR(a.angle.x(), 1e-4 + 0.1 * dt, 1e-18);  // the twist about n is not rolling
  EXPECT_NEAR(a.torque.x(), -k_r * 2e-4 - c_r * 0.1, 1e-15);
  EXPECT_EQ(a.torque.z(), 0.0);
  EXPECT_NEAR(a.elastic, 0.5 * k_r * 4e-8, 1e-20);
  EXPECT_NEAR(a.power, -a.torque.x() * 0.1, 1e-18);
  const RollingSpring b = rolling_spring(Vec3(0, 3e-3, 0), Vec3(0, 10.0, 0), n, k_r, c_r, mu_r, r_star, f_n, dt);
  EXPECT_TRUE(b.plastic);
  EXPECT_NEAR(b.torque.y(), -mu_r * r_star * f_n, 1e-15);
  EXPECT_NEAR(b.angle.y(), mu_r * r_star * f_n / k_r, 1e-15);
  EXPECT_GT(b.power, 0.0);
  // k_r = 2.25 k_n μ_r² R*² and C_r = 2 η_r √(I_r k_r).
  EXPECT_DOUBLE_EQ(epsd_rolling_stiffness(1e5, 0.2, 0.005), 2.25 * 1e5 * 0.04 * 2.5e-5);
  EXPECT_DOUBLE_EQ(epsd_rolling_damping(0.5, 4.0, 9.0), 6.0);
}

TEST(RollingSpringLaw, LammpsFormHoldsSpringAndDashpotTogetherAndResetsTheSpringBehindTheDashpot) {
  // contact.rolling_limit "spring_and_dashpot" (LAMMPS 29Sep2021 rolling sds): below the limit the
  // same torque; the spring 2e-3 N m plus the dashpot 0.01 x 0.15 = 1.5e-3 N m exceeds the limit 2e-3
  // N m while the spring alone does not, so silodem's default gives −(k θ + C ω), this form the
  // limit, with the spring reset to θ = (M_m − C ω)/k so that spring plus dashpot make the limit.
  const Vec3 n(0, 0, 1);
  const double k_r = 2.0, c_r = 0.01, mu_r = 0.1, r_star = 0.01, f_n = 2.0, dt = 1e-3, w = 0.15;
  const Vec3 angle(0, 1e-3 - w * dt, 0), spin(0, w, 0);  // grown by ω Δt to θ = 1e-3 rad: k θ = 2e-3 N m
  const RollingSpring own = rolling_spring(angle, spin, n, k_r, c_r, mu_r, r_star, f_n, dt);
  EXPECT_FALSE(own.plastic);
  EXPECT_NEAR(own.torque.y(), -(2e-3 + c_r * w), 1e-15);
  const RollingSpring sds = rolling_spring(angle, spin, n, k_r, c_r, mu_r, r_star, f_n, dt, true);
  EXPECT_TRUE(sds.plastic);
  EXPECT_NEAR(sds.torque.y(), -mu_r * r_star * f_n, 1e-15);
  EXPECT_NEAR(sds.angle.y(), (mu_r * r_star * f_n - c_r * w) / k_r, 1e-15);
  // Below the limit both forms agree, and without a dashpot they are one law.
  const Vec3 small(0, 1e-4, 0);
  EXPECT_EQ(rolling_spring(small, spin, n, k_r, c_r, mu_r, r_star, f_n, dt).torque,
            rolling_spring(small, spin, n, k_r, c_r, mu_r, r_star, f_n, dt, true).torque);
  const Vec3 big(0, 5e-3, 0);
  EXPECT_EQ(rolling_spring(big, spin, n, k_r, 0.0, mu_r, r_star, f_n, dt).angle,
            rolling_spring(big, spin, n, k_r, 0.0, mu_r, r_star, f_n, dt, true).angle);
}

TEST(SlipLeverArm, TheRadiusArmRollsAtROmegaTheContactPointArmAtRMinusHalfTheOverlap) {
  // A ball (r = 1 cm) on a floor ball, overlap 1e-4 m, rolling at v = r ω: with the radius as the
  // slip velocity's lever arm (contact.slip_lever_arm "radius", LAMMPS's) it does not slip; with
  // the contact-point arm r − δ/2 it slips at u δ/(2r), and the spring grows by that times Δt.
  PairParams pp;
  pp.friction = 0.5;
  pp.shear_ratio = 2.0 / 7.0;
  ContactState s{};
  const double u = 0.7, r = 0.01;
  s.delta = 1e-4;
  s.n = Vec3(0, 0, 1);
  s.v_rel = Vec3(u, 0, 0);
  s.w_i = Vec3(0, u / r, 0);
  s.w_j = Vec3::Zero();
  s.r_i = r;
  s.r_j = 1000.0;
  s.m_eff = 1e-3;
  s.k_n = 1e5;
  s.c_n = 0.0;
  s.pair = &pp;
  s.dt = 1e-5;
  s.slip_arm_overlap = 0.0;
  const auto at_radius = interact<NormalModel::Linear, TangentialModel::LinearHistory, RollingModel::None, false>(s);
  EXPECT_LT(at_radius.spring.norm(), 1e-20);
  s.slip_arm_overlap = 0.5;
  const auto at_contact = interact<NormalModel::Linear, TangentialModel::LinearHistory, RollingModel::None, false>(s);
  EXPECT_NEAR(at_contact.spring.x(), s.dt * u * s.delta / (2 * r), 1e-18);
  // The torque's arm is r − δ/2 either way: torque_i = −(r − δ/2) n × F_t.
  EXPECT_NEAR(at_contact.torque_i.y(), -(r - 0.5 * s.delta) * at_contact.force.x(), 1e-18);
}
