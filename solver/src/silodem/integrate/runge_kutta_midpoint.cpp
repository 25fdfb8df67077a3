#include "silodem/integrate/runge_kutta_midpoint.hpp"

#include "silodem/core/parallel.hpp"

namespace silodem {

double RungeKuttaMidpoint::viscous_power(const Particles& p) const {
  double sum = 0.0;  // in ball order: the same bits on any thread count
  for (std::size_t i = 0; i < p.n_mobile; ++i) sum += p.m[i] * p.v[i].squaredNorm();
  return mu_ * sum;
}

StepReport RungeKuttaMidpoint::step(Particles& p, const ForceEvaluation& eval, double dt) {
  const long n = long(p.n_mobile);
  x0_.resize(p.n_mobile), v0_.resize(p.n_mobile), v_half_.resize(p.n_mobile);
  const double p_start = mu_ > 0.0 ? viscous_power(p) : 0.0;
  // Stage 1 (8): Euler to the half step with ü_n (a_, α_: the forces at the accepted state).
  SILODEM_PARALLEL_FOR
  for (long il = 0; il < n; ++il) {
    const std::size_t i = std::size_t(il);
    x0_[i] = p.x[i], v0_[i] = p.v[i];
    p.x[i] += 0.5 * dt * p.v[i];
    p.v[i] += 0.5 * dt * (a_[i] - mu_ * v0_[i]);
  }
  if (p.rotating) {
    w0_.resize(p.n_mobile);
    SILODEM_PARALLEL_FOR
    for (long il = 0; il < n; ++il) {
      const std::size_t i = std::size_t(il);
      w0_[i] = p.w[i];
      p.w[i] += 0.5 * dt * alpha_[i];
    }
  }
  eval(p);
  // Stage 2 (9): the full step with the slopes at the half step.
  SILODEM_PARALLEL_FOR
  for (long il = 0; il < n; ++il) {
    const std::size_t i = std::size_t(il);
    v_half_[i] = p.v[i];
    p.x[i] = x0_[i] + dt * v_half_[i];
    p.v[i] = v0_[i] + dt * (p.f[i] / p.m[i] + g_ - mu_ * v_half_[i]);
  }
  if (p.rotating) {
    SILODEM_PARALLEL_FOR
    for (long il = 0; il < n; ++il) {
      const std::size_t i = std::size_t(il);
      p.w[i] = w0_[i] + dt * p.t[i] / p.inertia(i);
    }
  }
  StepReport rep;
  rep.totals = eval(p);  // the accepted state: the next step's ü_n
  rep.force_evaluations = 2;
  accelerations_from_forces(p, a_);
  angular_from_torques(p, alpha_);
  if (mu_ > 0.0) rep.viscous_dissipated = 0.5 * (p_start + viscous_power(p)) * dt;
  return rep;
}

}  // namespace silodem
