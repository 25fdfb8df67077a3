#pragma once
// The largest time step at which a scheme stays stable on one linear spring–dashpot contact
// (ω0 = √(k/m_eff), ζ = c/(2√(k m_eff))). A case whose Δt exceeds it for its stiffest pair is
// refused at load time: every such run blows up, and the loader can say why.
#include <utility>

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

/// Spectral radius of the explicit midpoint (two-stage Runge–Kutta) step on ü = −ω²u − 2ζωu̇ at
/// Ω = ωΔt: the largest |1 + z + z²/2| over z = Δt λ, λ the oscillator's two roots. Above 1 for
/// every Ω > 0 when ζ = 0 (docs/theory.md §7.8).
double midpoint_spectral_radius(double Omega, double zeta);

/// The artificial viscosities μ (1/s, acting as −μ v) at which the midpoint scheme is stable on a
/// mode ω with damping ratio ζ at Δt: [lo, hi], or {NaN, NaN} when none is.
std::pair<double, double> midpoint_viscosity_window(double omega, double zeta, double dt);

}  // namespace silodem
