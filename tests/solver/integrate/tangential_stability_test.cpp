// The time-step limits of the tangential mode (integrate/stability.hpp, stable_tangential_time_step;
// docs/theory.md §7.7) against the schemes themselves, on a ball held on a floor by a sticking
// linear history spring through the real frictional force loop: just above an exact limit the slip
// grows without bound, just below it stays bounded. bench_stability measures the limits to 1e-4.
#include <gtest/gtest.h>

#include <cmath>

#include "floor_contact.hpp"
#include "silodem/integrate/stability.hpp"

using namespace silodem;
using silodem::floor_test::FloorContact;
using silodem::floor_test::FloorSpec;

namespace {

FloorSpec spec_for(double zeta_t) { return floor_test::sticking_spec(zeta_t); }

double omega_t(const FloorSpec& s) {
  FloorContact c(s, 1e-6);
  return std::sqrt(s.shear_ratio * s.k_n / c.slip_mass());
}

/// Largest slip amplitude over `steps` steps relative to the start (√ of the energy ratio);
/// infinite if the ball leaves its resting height by half its overlap (the normal mode failed).
double growth(const FloorSpec& s, const IntegratorSpec& scheme, double dt, int steps) {
  FloorContact c(s, dt);
  c.start_slip_mode(1e-3);
  auto in = floor_test::make_scheme(scheme, Vec3(0, 0, -s.g));
  const double e0 = c.slip_energy(in->reset(c.p, c.eval));
  double worst = 1.0;
  for (int n = 0; n < steps; ++n) {
    const StepReport r = c.step(*in, dt);
    if (!(std::abs(c.lift()) < 0.5 * c.static_overlap())) return INFINITY;
    worst = std::max(worst, std::sqrt(c.slip_energy(r.totals) / e0));
    if (!(worst < 1e6)) return INFINITY;
  }
  return worst;
}

struct Case {
  const char* name;
  IntegratorSpec spec;
};

std::vector<Case> cases() {
  IntegratorSpec vv, vv_half, pc1, pc2, pc3;
  vv.scheme = vv_half.scheme = Scheme::VelocityVerlet;
  vv_half.half_step_dashpot = true;
  pc2.max_corrector_passes = 2;
  pc3.max_corrector_passes = 3;
  return {{"velocity_verlet", vv}, {"velocity_verlet_half_step", vv_half}, {"predictor_corrector_m1", pc1},
          {"predictor_corrector_m2", pc2}, {"predictor_corrector_m3", pc3}};
}

}  // namespace

// The limit is exact for velocity Verlet and for odd pass counts; for even ones it is exact at
// ζ_t = 0 and below the true limit otherwise (docs/theory.md §7.7), so only their lower side is tested.
TEST(TangentialStability, EverySchemeIsBoundedJustBelowAndBlowsUpJustAboveItsLimit) {
  for (const auto& c : cases())
    for (const double zeta : {0.0, 0.1, 0.5, 0.9}) {
      const FloorSpec s = spec_for(zeta);
      const double dt = stable_tangential_time_step(c.spec, omega_t(s), zeta).dt_max;
      EXPECT_LT(growth(s, c.spec, 0.97 * dt, 4000), 50.0) << c.name << ", zeta_t " << zeta;
      const bool exact = c.spec.scheme == Scheme::VelocityVerlet || c.spec.max_corrector_passes % 2 == 1 || zeta == 0.0;
      if (exact) {
        EXPECT_GT(growth(s, c.spec, 1.03 * dt, 4000), 1e3) << c.name << ", zeta_t " << zeta;
      }
    }
}

TEST(TangentialStability, TheNormalModeRuleAdmitsUnstableTangentialSteps) {
  // What the case loader applies to the tangential mode today (case/feasibility.cpp): the normal
  // mode's limit at ω_t. Velocity Verlet with the predicted velocity and the predictor–corrector
  // blow up below it; the half-step variant's limit is the normal one.
  for (const auto& c : cases()) {
    const FloorSpec s = spec_for(0.1);
    const double dt = 0.97 * stable_time_step(c.spec, omega_t(s), 0.1).dt_max;
    if (c.spec.half_step_dashpot) {
      EXPECT_LT(growth(s, c.spec, dt, 4000), 50.0) << c.name;
    } else {
      EXPECT_GT(growth(s, c.spec, dt, 4000), 1e3) << c.name;
    }
  }
}
