#pragma once
// Velocity Verlet, the baseline most DEM codes use (LAMMPS fix nve/sphere): kick–drift–force–kick.
// Not in the paper. The dashpot needs a velocity at the new position, which the scheme has not yet
// computed. LAMMPS uses the half-step velocity (`half_step`); that lags the dashpot by Δt/2 and,
// at high damping, misses the restitution by far more than 3ζΩ (ζ = 0.9, t_c/Δt = 50: |Δe/e| ≈ 0.74).
// The default `predicted` uses v_{n+1/2} + ½Δt ü_n, a first-order estimate of v_{n+1}, and meets
// the plain-scheme bound at every ζ (references/restitution.hpp).
#include "silodem/integrate/integrator.hpp"

namespace silodem {

class VelocityVerlet final : public Integrator {
 public:
  VelocityVerlet(Vec3 gravity, bool half_step_dashpot)
      : Integrator(std::move(gravity)), half_step_(half_step_dashpot) {}
  StepReport step(Particles& p, const ForceEvaluation& eval, double dt) override;

 private:
  bool half_step_;
  std::vector<Vec3> v_half_, w_half_;

 public:
  std::size_t bytes() const override { return Integrator::bytes() + heap_bytes(v_half_) + heap_bytes(w_half_); }
};

}  // namespace silodem
