#include "silodem/integrate/velocity_verlet.hpp"

#include "silodem/core/parallel.hpp"

namespace silodem {

StepReport VelocityVerlet::step(Particles& p, const ForceEvaluation& eval, double dt) {
  const long n = long(p.n_mobile);
  v_half_.resize(p.n_mobile);
  a_.resize(p.n_mobile);
  SILODEM_PARALLEL_FOR
  for (long il = 0; il < n; ++il) {
    const std::size_t i = std::size_t(il);
    v_half_[i] = p.v[i] + 0.5 * dt * a_[i];
    p.x[i] += dt * v_half_[i];
    // The velocity the dashpot sees at the new position.
    p.v[i] = half_step_ ? v_half_[i] : Vec3(v_half_[i] + 0.5 * dt * a_[i]);
  }
  // Rotation by the same kick–drift–kick, with the same predicted rate at the evaluation: the
  // tangential dashpot and the slip velocity see ω as the normal dashpot sees v.
  if (p.rotating) {
    w_half_.resize(p.n_mobile);
    alpha_.resize(p.n_mobile);
    SILODEM_PARALLEL_FOR
    for (long il = 0; il < n; ++il) {
      const std::size_t i = std::size_t(il);
      w_half_[i] = p.w[i] + 0.5 * dt * alpha_[i];
      p.w[i] = half_step_ ? w_half_[i] : Vec3(w_half_[i] + 0.5 * dt * alpha_[i]);
    }
  }
  StepReport rep;
  rep.totals = eval(p);
  rep.force_evaluations = 1;
  // ü (2) and the closing kick in one pass.
  SILODEM_PARALLEL_FOR
  for (long il = 0; il < n; ++il) {
    const std::size_t i = std::size_t(il);
    a_[i] = p.f[i] / p.m[i] + g_;
    p.v[i] = v_half_[i] + 0.5 * dt * a_[i];
  }
  if (p.rotating) {
    SILODEM_PARALLEL_FOR
    for (long il = 0; il < n; ++il) {
      const std::size_t i = std::size_t(il);
      alpha_[i] = p.t[i] / p.inertia(i);
      p.w[i] = w_half_[i] + 0.5 * dt * alpha_[i];
    }
  }
  return rep;
}

}  // namespace silodem
