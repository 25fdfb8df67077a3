#pragma once
// Escape from the cohesion zone (docs/theory.md §2a): a free pair separating at u0 from δ = 0 feels
// −k s in the zone 0 ≤ s ≤ |δ_c| and nothing beyond. Escape iff u0 > v* = ω_c|δ_c| = N_max/√(k m_eff);
// then it leaves at √(u0² − v*²); otherwise it turns at the gap u0/ω_c.
#include <cfloat>
#include <cmath>
#include <numbers>

#include "references/restitution.hpp"

namespace references {

struct CohesionPair {
  double reach;        // |δ_c| = p_N g m_min / k
  double escape_speed; // v*
  bool escapes;
  double final_speed;  // when it escapes
  double turning_gap;  // when captured: s_max = u0/ω_c
};

inline CohesionPair cohesion_separation(double k, double m_eff, double m_min, double p_n, double g, double u0) {
  CohesionPair r{};
  const double n_max = p_n * g * m_min;
  r.reach = n_max / k;
  r.escape_speed = n_max / std::sqrt(k * m_eff);
  r.escapes = u0 > r.escape_speed;
  r.final_speed = r.escapes ? std::sqrt(u0 * u0 - r.escape_speed * r.escape_speed) : 0.0;
  r.turning_gap = r.escapes ? r.reach : u0 / std::sqrt(k / m_eff);
  return r;
}

/// Relative error bounds a scheme with step Δt meets on such a pair, Ω = Δt·ω_c, ω_c = √(k/m_eff)
/// (the cohesion check's "scheme_bound"). The harmonic part carries the elastic bound of one
/// collision, Ω²/8 + 0.5Ω³ (scheme_error_bound at ζ = 0, restitution.hpp).
/// Escape speed: the zone's edge |δ_c| is seen up to one step late, so the force N_max = k|δ_c|
/// acts up to Δt too long: |Δv_f| ≤ N_max Δt/m_eff = Ω ω_c|δ_c| = Ω v*.
inline double escape_speed_bound(const CohesionPair& p, double omega_dt) {
  return omega_dt * p.escape_speed / p.final_speed + scheme_error_bound(0.0, omega_dt);
}

/// Turning gap u0/ω_c: the largest sampled gap lies below the crest of the sine by at most
/// 1 − cos(Ω/2) ≤ Ω²/8, and the integrated amplitude is off by at most Ω²/8 (velocity Verlet's is
/// (1 + Ω²/8) u0/ω_c); positions of size |x| ≤ `max_abs_position` round by at most half an ulp per
/// step and ball over the (π/2)/Ω steps to the turn, and once more when the gap is formed.
inline double turning_gap_bound(const CohesionPair& p, double omega_dt, double max_abs_position) {
  const double steps = 0.5 * std::numbers::pi / omega_dt + 2.0;
  return 2.0 * scheme_error_bound(0.0, omega_dt) + steps * DBL_EPSILON * max_abs_position / p.turning_gap;
}

/// The energy the spring takes away (½k δ_c² escaped, ½ m_eff u0² captured): an escaping pair lets
/// go up to one step's travel v_f Δt past |δ_c|, which changes ½kδ² by 2 v_f Δt/|δ_c| = 2Ω v_f/v*;
/// a captured one lets go at the sampled turn, where the energy goes with the gap squared.
inline double cohesion_energy_bound(const CohesionPair& p, double omega_dt, double max_abs_position) {
  return p.escapes ? 2.0 * omega_dt * p.final_speed / p.escape_speed + scheme_error_bound(0.0, omega_dt)
                   : 2.0 * turning_gap_bound(p, omega_dt, max_abs_position);
}

}  // namespace references
