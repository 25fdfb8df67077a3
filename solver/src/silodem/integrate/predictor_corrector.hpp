#pragma once
// The paper's predictor–corrector (Algorithms 3–5, equations (18)–(26)).
#include "silodem/integrate/integrator.hpp"

namespace silodem {

class PredictorCorrector final : public Integrator {
 public:
  /// `max_passes` = 1 is the explicit form (j = 0 only); more passes are the multiple corrector
  /// (25), stopped by `stop` at tolerance `eps_acc` (ε_ü) or at the pass limit.
  PredictorCorrector(Vec3 gravity, int max_passes, CorrectorStop stop, double eps_acc)
      : Integrator(std::move(gravity)), max_passes_(max_passes), stop_(stop), eps_(eps_acc) {}

  StepReport step(Particles& p, const ForceEvaluation& eval, double dt) override;
  std::optional<double> corrector_tolerance() const override {
    return max_passes_ > 1 ? std::optional<double>(eps_) : std::nullopt;
  }

 private:
  /// One corrector pass on ω (22)/(25) at the evaluated torques; returns its residual.
  double rotation_corrector(Particles& p, double dt);
  /// The stop test's measure of one ball's pass: Δ = Δü⁽ʲ⁾, Δ_prev = Δü⁽ʲ⁻¹⁾, a = ü⁽ʲ⁾ (or ω̇, times r).
  double residual(const Vec3& delta, const Vec3& delta_prev, const Vec3& a) const;
  int max_passes_;
  CorrectorStop stop_;
  double eps_;
  std::vector<Vec3> xp_, vp_, a_pass_, da_prev_;
  std::vector<Vec3> wp_, alpha_pass_, dalpha_prev_;  // rotation, the same scheme on ω

 public:
  std::size_t bytes() const override {
    return Integrator::bytes() + heap_bytes(xp_) + heap_bytes(vp_) + heap_bytes(a_pass_) + heap_bytes(da_prev_) +
           heap_bytes(wp_) + heap_bytes(alpha_pass_) + heap_bytes(dalpha_prev_);
  }
};

}  // namespace silodem
