#include "silodem/integrate/integrator.hpp"

#include "silodem/checkpoint/archive.hpp"

#include <cmath>
#include <stdexcept>

#include "silodem/core/parallel.hpp"
#include "silodem/integrate/predictor_corrector.hpp"
#include "silodem/integrate/runge_kutta_midpoint.hpp"
#include "silodem/integrate/velocity_verlet.hpp"

namespace silodem {

void Integrator::accelerations_from_forces(const Particles& p, std::vector<Vec3>& out) const {
  out.resize(p.n_mobile);
  const long n = long(p.n_mobile);
  SILODEM_PARALLEL_FOR
  for (long i = 0; i < n; ++i) out[std::size_t(i)] = p.f[std::size_t(i)] / p.m[std::size_t(i)] + g_;  // (2)
}

void Integrator::angular_from_torques(const Particles& p, std::vector<Vec3>& out) const {
  if (!p.rotating) return out.clear();
  out.resize(p.n_mobile);
  const long n = long(p.n_mobile);
  SILODEM_PARALLEL_FOR
  for (long il = 0; il < n; ++il) out[std::size_t(il)] = p.t[std::size_t(il)] / p.inertia(std::size_t(il));
}

ForceTotals Integrator::reset(Particles& p, const ForceEvaluation& eval) {
  const ForceTotals t = eval(p);
  accelerations_from_forces(p, a_);
  angular_from_torques(p, alpha_);
  return t;
}

std::unique_ptr<Integrator> make_integrator(const IntegratorSpec& spec, const Vec3& gravity) {
  if (spec.scheme == Scheme::VelocityVerlet) return std::make_unique<VelocityVerlet>(gravity, spec.half_step_dashpot);
  if (spec.scheme == Scheme::RungeKuttaMidpoint) return std::make_unique<RungeKuttaMidpoint>(gravity, spec.viscosity);
  // ε_ü = p_ü |g| (26); with zero gravity the paper's scale is undefined, so use p_ü in m/s².
  const double g_abs = gravity.norm();
  const double eps = spec.corrector_stop == CorrectorStop::Relative ? spec.relative_tolerance
                                                                     : spec.p_acc * (g_abs > 0.0 ? g_abs : 1.0);
  return std::make_unique<PredictorCorrector>(gravity, spec.max_corrector_passes, spec.corrector_stop, eps);
}

void Integrator::permute_mobile(const std::vector<std::uint32_t>& order) {
  if (a_.empty()) return;  // before reset(): no ü to carry yet
  if (a_.size() != order.size()) throw std::logic_error("Integrator::permute_mobile: ü is for another set of balls");
  permute_front(a_, order);
  if (!alpha_.empty()) permute_front(alpha_, order);
}

void Integrator::serialize(Archive& a, const Particles& p) {
  a & a_;
  if (p.rotating) a & alpha_;  // only a rotating scene has them: a frictionless checkpoint keeps its layout
  if (a.loading() && (a_.size() != p.n_mobile || (p.rotating && alpha_.size() != p.n_mobile)))
    throw CheckpointError("checkpoint payload is damaged (accelerations for another number of balls)");
}

}  // namespace silodem
