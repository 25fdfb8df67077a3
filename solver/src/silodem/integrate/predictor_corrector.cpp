#include "silodem/integrate/predictor_corrector.hpp"

#include <algorithm>
#include <cmath>

#include "silodem/core/parallel.hpp"

namespace silodem {

double PredictorCorrector::residual(const Vec3& delta, const Vec3& delta_prev, const Vec3& a) const {
  if (stop_ == CorrectorStop::PaperLiteral) return delta.norm();
  const double change = (delta - delta_prev).norm();
  if (stop_ == CorrectorStop::FixedPoint) return change;
  // Seed 003's (31): the change relative to the acceleration itself. A ball whose acceleration
  // vanishes (at rest in a bed) can only pass with no change at all: there it spends the pass limit.
  const double size = a.norm();
  return size > 0.0 ? change / size : (change > 0.0 ? INFINITY : 0.0);
}

double PredictorCorrector::rotation_corrector(Particles& p, double dt) {
  const long nl = long(p.n_mobile);
  angular_from_torques(p, alpha_pass_);
  double worst = 0.0;
#if defined(_OPENMP)
#pragma omp parallel for schedule(static) reduction(max : worst) num_threads(detail::g_threads) \
    if (detail::g_threads > 1)
#endif
  for (long il = 0; il < nl; ++il) {
    const std::size_t i = std::size_t(il);
    const Vec3 dalpha = alpha_pass_[i] - alpha_[i];
    // As an acceleration of the ball's surface, r |Δω̇|, so that one ε_ü (26) covers both.
    const double r = stop_ == CorrectorStop::Relative ? residual(dalpha, dalpha_prev_[i], alpha_pass_[i])
                                                       : p.r[i] * residual(dalpha, dalpha_prev_[i], alpha_pass_[i]);
    worst = std::max(worst, r);
    dalpha_prev_[i] = dalpha;
    p.w[i] = wp_[i] + 0.5 * dt * dalpha;
  }
  return worst;
}

StepReport PredictorCorrector::step(Particles& p, const ForceEvaluation& eval, double dt) {
  const std::size_t n = p.n_mobile;
  StepReport rep;
  xp_.resize(n);
  vp_.resize(n);
  da_prev_.assign(n, Vec3::Zero());  // the predictor assumes Δü = 0
  // Predictor (18)(19): constant acceleration ü = ü(t_1) over the step.
  const long nl = long(n);
  SILODEM_PARALLEL_FOR
  for (long il = 0; il < nl; ++il) {
    const std::size_t i = std::size_t(il);
    vp_[i] = p.v[i] + a_[i] * dt;
    xp_[i] = p.x[i] + p.v[i] * dt + 0.5 * dt * dt * a_[i];
    p.v[i] = vp_[i];
    p.x[i] = xp_[i];
  }
  // Rotation by the same scheme on ω (the orientation of a sphere is never needed). The history
  // laws see each pass as a trial from the committed state (forces/contact_history.hpp).
  if (p.rotating) {
    wp_.resize(n);
    dalpha_prev_.assign(n, Vec3::Zero());
    alpha_.resize(n);
    SILODEM_PARALLEL_FOR
    for (long il = 0; il < nl; ++il) {
      const std::size_t i = std::size_t(il);
      wp_[i] = p.w[i] + alpha_[i] * dt;
      p.w[i] = wp_[i];
    }
  }
  for (int pass = 0; pass < max_passes_; ++pass) {
    eval(p);
    ++rep.force_evaluations;
    accelerations_from_forces(p, a_pass_);
    double worst = p.rotating ? rotation_corrector(p, dt) : 0.0;  // a max: the same for any thread count
#if defined(_OPENMP)
#pragma omp parallel for schedule(static) reduction(max : worst) num_threads(detail::g_threads) \
    if (detail::g_threads > 1)
#endif
    for (long il = 0; il < nl; ++il) {
      const std::size_t i = std::size_t(il);
      // Out-of-balance acceleration (20)(21)/(25): Δü⁽ʲ⁾ = ü(u⁽ʲ⁾, u̇⁽ʲ⁾) − ü(t_1).
      const Vec3 da = a_pass_[i] - a_[i];
      // Stop test (26). docs/model.md §5.3 Reading: the literal max|Δü⁽ʲ⁾| < ε_ü cannot be met during an
      // impact, so the default is the fixed-point residual max|Δü⁽ʲ⁾ − Δü⁽ʲ⁻¹⁾| (Δü⁽⁻¹⁾ = 0).
      const double r = residual(da, da_prev_[i], a_pass_[i]);
      worst = std::max(worst, r);
      da_prev_[i] = da;
      // Corrector (22)(23)/(25): acceleration linear over the step, so the position gains the exact
      // integral Δü Δt²/6, added to the predictor (docs/model.md §5.2, §5.3).
      p.v[i] = vp_[i] + 0.5 * dt * da;
      p.x[i] = xp_[i] + (dt * dt / 6.0) * da;
    }
    rep.corrector_passes = pass + 1;
    rep.corrector_residual = worst;
    if (worst < eps_) break;
  }
  // ü at the accepted state is the next step's ü(t_1) (Algorithm 5 line 12).
  rep.totals = eval(p);
  ++rep.force_evaluations;
  accelerations_from_forces(p, a_);
  angular_from_torques(p, alpha_);
  return rep;
}

}  // namespace silodem
