#include "silodem/integrate/velocity_verlet.hpp"

namespace silodem {

StepReport VelocityVerlet::step(Particles& p, const ForceEvaluation& eval, double dt) {
  const std::size_t n = p.n_mobile;
  v_half_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    v_half_[i] = p.v[i] + 0.5 * dt * a_[i];
    p.x[i] += dt * v_half_[i];
    // The velocity the dashpot sees at the new position.
    p.v[i] = half_step_ ? v_half_[i] : Vec3(v_half_[i] + 0.5 * dt * a_[i]);
  }
  StepReport rep;
  rep.totals = eval(p);
  rep.force_evaluations = 1;
  accelerations_from_forces(p, a_);
  for (std::size_t i = 0; i < n; ++i) p.v[i] = v_half_[i] + 0.5 * dt * a_[i];
  return rep;
}

}  // namespace silodem
