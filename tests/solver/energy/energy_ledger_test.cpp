// The ledger's bookkeeping on synthetic states, and its balance on a real integrated collision.
#include <gtest/gtest.h>

#include <cmath>

#include "silodem/energy/energy_ledger.hpp"
#include "silodem/forces/force_field.hpp"
#include "silodem/integrate/integrator.hpp"
#include "silodem/neighbour/neighbour_list.hpp"

using namespace silodem;

TEST(EnergyLedger, TrapezoidalPowersCohesionExitsAndInjection) {
  Particles p;
  p.add({Vec3(0, 0, 1), Vec3(2, 0, 0), 0.01, 1.0, 1, 0, 0, "a"}, false);
  EnergyLedger L(Vec3(0, 0, -10));
  ForceTotals t0;
  t0.p_dissipated = 1.0;
  L.start(p, t0, 0.0);
  EXPECT_DOUBLE_EQ(L.state().initial, 2.0 + 10.0);  // ½·1·2² + m g z
  ForceTotals t1;
  t1.p_dissipated = 3.0;
  t1.p_cohesion = 4.0;
  t1.elastic_cohesion = 0.1;  // of the 0.5·4·0.5 = 1.0 J that flowed in, 0.1 J is still held
  L.record(p, t1, 0.5, 0.5);
  EXPECT_DOUBLE_EQ(L.state().dissipated, 0.5 * (1.0 + 3.0) * 0.5);
  EXPECT_DOUBLE_EQ(L.state().cohesion_removed, 1.0 - 0.1);
  EXPECT_DOUBLE_EQ(L.state().elastic, 0.1);
  L.inject(2.0, Vec3(0, 0, 3), Vec3(0, 0, -1));
  EXPECT_DOUBLE_EQ(L.state().injected, 1.0 + 60.0);
}

TEST(EnergyLedger, BalancesAnIntegratedDampedCollision) {
  // Two balls, ζ ≈ 0.2, predictor–corrector: the residual must stay at the integrator's own
  // O(ζΩ) error, and the dissipated energy must match ½ m_eff v² (1 − e²) to the same order.
  Particles p;
  const double r = 0.005, m = 2500 * 4.0 / 3.0 * M_PI * r * r * r;
  p.add({Vec3(-r - 1e-5, 0, 0), Vec3(0.1, 0, 0), r, m, 2e5, 6.0, 0, "a"}, false);
  p.add({Vec3(r + 1e-5, 0, 0), Vec3(-0.1, 0, 0), r, m, 2e5, 6.0, 0, "b"}, false);
  ContactSpec spec;
  NeighbourList nl(0.001, 0.0);
  auto field = make_force_field(spec, 0.0);
  const ForceEvaluation eval = [&](Particles& q) { nl.update(q); return field->compute(q, nl); };
  auto in = make_integrator(IntegratorSpec{}, Vec3::Zero());
  EnergyLedger L(Vec3::Zero());
  L.start(p, in->reset(p, eval), 0.0);
  const double dt = 1e-7;
  for (int n = 1; n <= 5000; ++n) L.record(p, in->step(p, eval, dt).totals, n * dt, dt);
  const double m_eff = m / 2, e = -(p.v[0].x() - p.v[1].x()) / 0.2;
  EXPECT_LT(L.max_abs_relative_drift(), 1e-3);
  EXPECT_NEAR(L.state().dissipated, 0.5 * m_eff * 0.04 * (1 - e * e), 1e-3 * 0.5 * m_eff * 0.04);
  EXPECT_NEAR(e, 0.552796, 2e-3);  // the test pair of docs/reference-codes.md: analytic e
}
