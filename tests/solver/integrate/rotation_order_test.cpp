// The order of every integrator on two smooth rotating problems with closed forms (docs/model.md
// §10.1, docs/theory.md §10.7), through the real frictional force loop: a ball on a floor whose
// slip is resisted viscously (the sliding law below its Coulomb cap: translation and spin, no
// history) and a ball held by a sticking linear history spring (the tangential mode). Neither has
// a non-smooth event: slip to roll's switch from sliding to rolling would add an O(Δt) error of
// its own to every scheme. Prints the table of reports/rotation_order.md.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "floor_contact.hpp"
#include "references/friction.hpp"

using namespace silodem;
using silodem::floor_test::FloorContact;
using silodem::floor_test::FloorSpec;

namespace {

struct SchemeCase {
  std::string name;
  IntegratorSpec spec;
  // Theoretical orders (docs/model.md §10.1): the spin and velocity updates are the translational
  // ones, so a force of the velocity keeps the dashpot's order (2, or 1 with the half-step
  // velocity, docs/theory.md §1d); the history spring grows by Δt times the velocity the
  // evaluation sees, which is v_{n+1} to O(Δt²) except with the half-step velocity: order 1.
  int viscous_order, spring_order;
};

std::vector<SchemeCase> schemes() {
  std::vector<SchemeCase> v;
  IntegratorSpec s;
  s.scheme = Scheme::VelocityVerlet;
  v.push_back({"velocity_verlet", s, 2, 1});
  s.half_step_dashpot = true;
  v.push_back({"velocity_verlet_half_step", s, 1, 2});
  for (int m : {1, 2, 3}) {
    IntegratorSpec pc;
    pc.max_corrector_passes = m;
    v.push_back({"predictor_corrector_m" + std::to_string(m), pc, 2, 1});
  }
  return v;
}

/// Largest error of (v, a ω) over the coarsest level's step times, relative to the start slip.
template <class Oracle>
double run_error(const FloorSpec& spec, const IntegratorSpec& scheme, double dt, double t_end, int sample_every,
                 bool slip_mode, double s0, const Oracle& oracle) {
  FloorContact c(spec, dt);
  if (slip_mode) c.start_slip_mode(s0);
  else c.p.v[0] = Vec3(s0, 0, 0);
  auto in = floor_test::make_scheme(scheme, Vec3(0, 0, -spec.g));
  in->reset(c.p, c.eval);
  const long steps = std::lround(t_end / dt);
  double worst = 0.0;
  for (long n = 1; n <= steps; ++n) {
    c.step(*in, dt);
    if (n % sample_every) continue;
    const double t = double(n) * dt;
    worst = std::max(worst, std::abs(c.p.v[0].x() - oracle.speed(t)) + c.arm() * std::abs(c.p.w[0].y() - oracle.spin(t)));
  }
  return worst / s0;
}

/// Least-squares slope of log(error) against log(Δt).
double fitted_order(const std::vector<double>& dt, const std::vector<double>& err) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = double(dt.size());
  for (std::size_t k = 0; k < dt.size(); ++k) {
    const double x = std::log(dt[k]), y = std::log(err[k]);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

constexpr int kLevels = 5;  // four halvings

// Tolerance of the fitted order: 0.1. The fit spans Δt0 to Δt0/16; the next term of the error
// expansion is relatively O(Δt/τ) ≤ 0.1 (viscous) or, for the first-order spring, the curvature of
// its decay 1 − e^{−x}, x = Ω_t ω_t t/4 ≤ 0.08 at the coarsest level: each bends the log–log line by
// at most about log2(1 + 0.1) = 0.14 between its ends, half that on the fit.
constexpr double kOrderTolerance = 0.1;

/// One row of reports/rotation_order.md.
void report(const char* problem, const SchemeCase& s, const std::vector<double>& err, double order, int expected) {
  std::printf("| %s | %s |", problem, s.name.c_str());
  for (std::size_t k = 0; k < err.size(); ++k) std::printf(" %.3e |", err[k]);
  std::printf(" %.3f | %d |\n", order, expected);
}

}  // namespace

TEST(RotationOrder, ViscousSlipConvergesAtTheDashpotOrderOfEachScheme) {
  // k_n = 1e5 N/m, m = 4 g: ω_n = 5000 rad/s. γ sets τ = m_t/γ = 1 ms; Δt = τ/10 … τ/160 keeps
  // ω_n Δt ≤ 0.5, and γ u0 = 1.1e-3 N stays below μ m g = 0.039 N: the law stays viscous.
  FloorSpec spec;
  spec.law = TangentialModel::CoulombSliding;
  spec.mu = 1.0;
  const double u0 = 1e-3, tau = 1e-3;
  FloorContact probe(spec, 1e-5);
  spec.sliding_damping = probe.slip_mass() / tau;
  const auto oracle = references::viscous_slip(u0, spec.sliding_damping, spec.m, probe.inertia(), probe.arm());
  ASSERT_NEAR(oracle.speed(1e3), 5.0 / 7.0 * u0, 1e-3 * u0);  // it ends rolling (a = r to 2e-5)
  for (const auto& s : schemes()) {
    std::vector<double> dt, err;
    for (int k = 0; k < kLevels; ++k) {
      dt.push_back(0.1 * tau / double(1 << k));
      err.push_back(run_error(spec, s.spec, dt.back(), 3.0 * tau, 1 << k, false, u0, oracle));
    }
    const double order = fitted_order(dt, err);
    report("viscous slip", s, err, order, s.viscous_order);
    EXPECT_NEAR(order, s.viscous_order, kOrderTolerance) << s.name;
  }
}

TEST(RotationOrder, StickingSpringConvergesAtTheSpringUpdateOrderOfEachScheme) {
  // ρ = 2/7: ω_t ≈ ω_n = 5000 rad/s. Ω_t = ω_t Δt = 0.05 … 0.003125 over one period; slip 1 mm/s,
  // spring ≤ 0.2 µm, its force ≤ 6e-3 N, far below μ m g (μ = 1e6).
  FloorSpec spec;
  const double s0 = 1e-3;
  FloorContact probe(spec, 1e-5);
  const auto oracle =
      references::sticking_slip(s0, spec.shear_ratio * spec.k_n, spec.m, probe.inertia(), probe.arm());
  const double t_end = 2.0 * M_PI / oracle.omega_t;
  for (const auto& s : schemes()) {
    std::vector<double> dt, err;
    for (int k = 0; k < kLevels; ++k) {
      dt.push_back(0.05 / oracle.omega_t / double(1 << k));
      err.push_back(run_error(spec, s.spec, dt.back(), t_end, 1 << k, true, s0, oracle));
    }
    const double order = fitted_order(dt, err);
    report("sticking spring", s, err, order, s.spring_order);
    EXPECT_NEAR(order, s.spring_order, kOrderTolerance) << s.name;
  }
}

TEST(RotationOrder, TheFirstOrderSpringUpdateIsANumericalDashpotOfRatioOmegaOverFour) {
  // docs/theory.md §7.7: growing the spring by Δt v_{n+1} instead of ∫v dt loads it as it will be
  // half a step later, F = −k_t(ξ + ½Δt v): a dashpot ½k_tΔt, ζ = Ω_t/4. Undamped, the step
  // matrix has det = 1 − Ω_t²/2 + O(Ω_t⁴), so the slip energy falls by that factor per step.
  // The half-step variant keeps the energy (to O(Ω_t²)). Tolerance 1 %: the energy of (v, ω, ξ)
  // differs from the eigen-amplitude by a phase-dependent O(Ω_t) = 2 %, which sampling after whole
  // periods reduces to O(Ω_t²) (measured ≤ 0.1 %).
  FloorSpec spec;
  FloorContact probe(spec, 1e-5);
  const double w_t = std::sqrt(spec.shear_ratio * spec.k_n / probe.slip_mass()), big_omega = 0.02;
  const double dt = big_omega / w_t;
  const int steps = int(std::lround(20.0 * 2.0 * M_PI / big_omega));  // 20 periods
  for (const auto& s : schemes()) {
    FloorContact c(spec, dt);
    c.start_slip_mode(1e-3);
    auto in = floor_test::make_scheme(s.spec, Vec3(0, 0, -spec.g));
    const double e0 = c.slip_energy(in->reset(c.p, c.eval));
    ForceTotals last;
    for (int n = 0; n < steps; ++n) last = c.step(*in, dt).totals;
    const double ratio = c.slip_energy(last) / e0;
    const double predicted = s.spec.half_step_dashpot ? 1.0 : std::pow(1.0 - 0.5 * big_omega * big_omega, steps);
    std::printf("%s: energy ratio %.4f, predicted %.4f\n", s.name.c_str(), ratio, predicted);
    EXPECT_NEAR(ratio / predicted, 1.0, 0.01) << s.name;
  }
}
