#pragma once
// The explicit two-stage Runge–Kutta (midpoint) scheme of seed 001 (Bogulsky & Bogulskaya 2011,
// eqs. (8)–(9); docs/theory.md §7.8), with its artificial viscosity: every mobile ball's velocity
// feels −μ v (eqs. (6)–(7), lab frame, in flight too; not its spin). Euler to the half step with
// the forces at t_n, then the full step with the forces at the half-step state:
//   x½ = x + ½Δt v,            v½ = v + ½Δt (f(x, v)/m + g − μ v)
//   x' = x + Δt v½,            v' = v + Δt (f(x½, v½)/m + g − μ v½)
// (ω by the same two stages with t/I). Two force evaluations per step. Without viscosity (or a
// dashpot) it is unstable on every contact: the spectral radius on an undamped oscillator is
// √(1 + Ω⁴/4); the case loader refuses a Δt outside the stable window (integrate/stability.hpp).
#include "silodem/integrate/integrator.hpp"

namespace silodem {

class RungeKuttaMidpoint final : public Integrator {
 public:
  RungeKuttaMidpoint(Vec3 gravity, double viscosity) : Integrator(std::move(gravity)), mu_(viscosity) {}
  StepReport step(Particles& p, const ForceEvaluation& eval, double dt) override;
  std::size_t bytes() const override {
    return Integrator::bytes() + heap_bytes(x0_) + heap_bytes(v0_) + heap_bytes(w0_) + heap_bytes(v_half_);
  }

 private:
  /// Σ μ m |v|²: the power the viscosity takes out at one state.
  double viscous_power(const Particles& p) const;
  double mu_;
  std::vector<Vec3> x0_, v0_, w0_, v_half_;
};

}  // namespace silodem
