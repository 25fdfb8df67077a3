// The time-step limits the case loader enforces (integrate/stability.hpp), checked against the
// integrators themselves on a spring–dashpot oscillator: just above a limit the motion grows
// without bound; just below an exact limit it stays bounded.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "silodem/integrate/predictor_corrector.hpp"
#include "silodem/integrate/stability.hpp"
#include "silodem/integrate/velocity_verlet.hpp"

using namespace silodem;

namespace {

/// Largest |x| over `steps` steps of m = 1, k = 1 (ω0 = 1), c = 2ζ, started at x = 1.
double peak(Integrator& in, double zeta, double dt, int steps) {
  Particles p;
  p.add({Vec3(1, 0, 0), Vec3::Zero(), 0.01, 1.0, 1.0, 0.0, 0, "b"}, false);
  const ForceEvaluation f = [zeta](Particles& q) {
    q.f[0] = Vec3(-q.x[0].x() - 2.0 * zeta * q.v[0].x(), 0.0, 0.0);
    return ForceTotals{};
  };
  in.reset(p, f);
  double worst = 1.0;
  for (int n = 0; n < steps && std::isfinite(worst); ++n) {
    in.step(p, f, dt);
    worst = std::max(worst, std::abs(p.x[0].x()));
  }
  return std::isfinite(worst) ? worst : INFINITY;
}

struct Scheme_ {
  IntegratorSpec spec;
  bool exact;  // the limit is the scheme's own (else only a bound beyond which it is unstable)
  std::unique_ptr<Integrator> make() const {
    if (spec.scheme == Scheme::VelocityVerlet) return std::make_unique<VelocityVerlet>(Vec3::Zero(), spec.half_step_dashpot);
    // ε = 0: every pass is taken, the worst case of the stop test.
    return std::make_unique<PredictorCorrector>(Vec3::Zero(), spec.max_corrector_passes, CorrectorStop::FixedPoint, 0.0);
  }
};

std::vector<Scheme_> schemes() {
  IntegratorSpec vv, vv_half, pc1, pc10;
  vv.scheme = vv_half.scheme = Scheme::VelocityVerlet;
  vv_half.half_step_dashpot = true;
  pc10.max_corrector_passes = 10;
  return {{vv, true}, {vv_half, true}, {pc1, false}, {pc10, false}};
}

}  // namespace

TEST(StabilityLimit, EverySchemeBlowsUpJustAboveItsLimit) {
  for (const auto& s : schemes())
    for (const double zeta : {0.0, 0.1, 0.5, 0.9}) {
      const double dt = 1.03 * stable_time_step(s.spec, 1.0, zeta).dt_max;
      EXPECT_GT(peak(*s.make(), zeta, dt, 4000), 1e3) << stable_time_step(s.spec, 1.0, zeta).rule << ", zeta " << zeta;
    }
}

TEST(StabilityLimit, VerletStaysBoundedJustBelowItsLimit) {
  for (const auto& s : schemes()) {
    if (!s.exact) continue;
    for (const double zeta : {0.0, 0.1, 0.5, 0.9}) {
      const double dt = 0.97 * stable_time_step(s.spec, 1.0, zeta).dt_max;
      EXPECT_LT(peak(*s.make(), zeta, dt, 4000), 50.0) << stable_time_step(s.spec, 1.0, zeta).rule << ", zeta " << zeta;
    }
  }
}

TEST(StabilityLimit, ExplicitPredictorCorrectorIsStableJustBelowTwoOverOmegaUndamped) {
  IntegratorSpec pc1;
  const double dt = 0.97 * stable_time_step(pc1, 1.0, 0.0).dt_max;
  PredictorCorrector in(Vec3::Zero(), 1, CorrectorStop::FixedPoint, 0.0);
  EXPECT_LT(peak(in, 0.0, dt, 4000), 50.0);
}
