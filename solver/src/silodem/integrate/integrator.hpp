#pragma once
// Time integrators see arrays, not contacts: they move the mobile balls and call back for the
// forces at the states they need. Each scheme lives in its own file; make_integrator() picks one.
#include <functional>
#include <memory>
#include <vector>

#include <optional>

#include "silodem/case/case_config.hpp"
#include "silodem/forces/force_field.hpp"
#include "silodem/scene/particles.hpp"

namespace silodem {

class Archive;

/// Evaluates p.f at the current p.x, p.v (and refreshes the neighbour list as needed).
using ForceEvaluation = std::function<ForceTotals(Particles&)>;

/// What one step did; `totals` are the force sums at the accepted end-of-step state.
struct StepReport {
  ForceTotals totals;
  int corrector_passes = 0;     // 0 for schemes without a corrector
  double corrector_residual = 0.0;
  int force_evaluations = 0;
  double viscous_dissipated = 0.0;  // J taken out by an artificial viscosity (the midpoint scheme's)
};

class Integrator {
 public:
  explicit Integrator(Vec3 gravity) : g_(std::move(gravity)) {}
  virtual ~Integrator() = default;

  /// Evaluates forces at the current state to know ü(t); call at start and after the ball set changed.
  ForceTotals reset(Particles& p, const ForceEvaluation& eval);
  virtual StepReport step(Particles& p, const ForceEvaluation& eval, double dt) = 0;

  /// ü_i = f_i/m_i + g (2) at the last accepted state, mobile balls only.
  const std::vector<Vec3>& acceleration() const { return a_; }
  /// ω̇_i = t_i / I_i (I = 2/5 m r²) at the last accepted state; empty unless the balls rotate.
  const std::vector<Vec3>& angular_acceleration() const { return alpha_; }
  /// The per-ball state a step carries (ü, and ω̇ for rotating balls), for balls handed to
  /// another process (mpi/domain.hpp).
  std::vector<Vec3>& carried_acceleration() { return a_; }
  std::vector<Vec3>& carried_angular_acceleration() { return alpha_; }
  /// Follows Particles::permute_mobile: ü (and ω̇) is the only per-ball state a step carries to the next.
  void permute_mobile(const std::vector<std::uint32_t>& order);
  /// Checkpoint: ü at the last accepted state, the only thing a step carries to the next (the
  /// schemes' other arrays are rewritten every step).
  void serialize(Archive& a, const Particles& p);
  /// Heap bytes of its per-ball state.
  virtual std::size_t bytes() const { return heap_bytes(a_) + heap_bytes(alpha_); }
  /// The tolerance a corrector's residual must fall under for a step to count as converged; none
  /// for schemes that do not iterate (and for the explicit, one-pass predictor–corrector).
  virtual std::optional<double> corrector_tolerance() const { return std::nullopt; }

 protected:
  void accelerations_from_forces(const Particles& p, std::vector<Vec3>& out) const;
  /// ω̇ from the torques, for rotating balls (out stays empty otherwise).
  void angular_from_torques(const Particles& p, std::vector<Vec3>& out) const;
  Vec3 g_;
  std::vector<Vec3> a_;
  std::vector<Vec3> alpha_;  // ω̇ at the last accepted state (rotating balls only)
};

std::unique_ptr<Integrator> make_integrator(const IntegratorSpec& spec, const Vec3& gravity);

}  // namespace silodem
