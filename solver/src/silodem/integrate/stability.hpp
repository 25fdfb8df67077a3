#pragma once
// The largest time step at which a scheme stays stable on one linear spring–dashpot contact
// (ω0 = √(k/m_eff), ζ = c/(2√(k m_eff))). A case whose Δt exceeds it for its stiffest pair is
// refused at load time: every such run blows up, and the loader can say why.
#include "silodem/case/case_config.hpp"

namespace silodem {

struct StabilityLimit {
  double dt_max;         // s
  const char* rule;      // the bound used, for the refusal message
};

/// Necessary, not sufficient: a ball squeezed between several contacts oscillates faster than
/// one pair, so a Δt just below this limit can still be unstable in a dense packing.
StabilityLimit stable_time_step(const IntegratorSpec& in, double omega0, double zeta);

/// The same for the tangential mode of a sticking linear history spring (ω_t = √(k_t/m_t), m_t =
/// 2/7 m* for spheres; ζ_t = γ_t/(2√(k_t m_t))). It differs from stable_time_step because the spring
/// is not moved by the scheme's position update but by the force law, ξ += v_t Δt with the velocity
/// the evaluation sees (docs/theory.md §7.7); a change of that update changes these limits.
StabilityLimit stable_tangential_time_step(const IntegratorSpec& in, double omega_t, double zeta_t);

}  // namespace silodem
