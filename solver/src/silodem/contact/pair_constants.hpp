#pragma once
// Everything that turns ball properties into pair constants: the series rule (11), the cohesion
// reach (10), and the one documented derivation of per-ball (k, c) from a contact time and a
// restitution (or damping ratio) — the same derived values are handed to every reference code.

namespace silodem::contact {

/// Series connection (11): k_ij = k_i k_j / (k_i + k_j); also used for c_ij. A zero constant
/// makes the pair constant zero (a dashpot-free ball gives a dashpot-free pair).
inline double series(double a, double b) { return (a + b) > 0.0 ? a * b / (a + b) : 0.0; }

/// Effective mass of a pair; a fixed (wall) ball has infinite mass, so m_eff = m_mobile.
inline double effective_mass(double m_i, double m_j, bool i_fixed, bool j_fixed) {
  if (i_fixed) return m_j;
  if (j_fixed) return m_i;
  return m_i * m_j / (m_i + m_j);
}

/// Cohesion reach (10): δ_c = −p_N |g| min(m_i, m_j) / k_ij (negative): the lighter ball's weight
/// sets the largest tensile force. Taken literally for wall balls too (their mass from density).
double cohesion_reach(double p_n, double g_abs, double m_min, double k_ij);

/// Closed-form behaviour of one linear spring–dashpot contact (docs/theory.md §1a/§1b), used both to
/// derive constants and to report what a case's constants mean.
struct ContactBehaviour {
  double omega0;       // √(k/m_eff)
  double zeta;         // c / (2√(k m_eff))
  double restitution;  // e
  double duration;     // t_c (overlap end unclamped, force end clamped)
};
ContactBehaviour contact_behaviour(double k, double c, double m_eff, bool clamp);

/// Damping ratio giving restitution e (inverse of contact_behaviour for fixed ω0), for either
/// contact-end rule. Unclamped: ζ = −ln e/√(π² + ln² e); clamped: solved by bisection.
double damping_ratio_for_restitution(double e, bool clamp);

/// Per-ball constants (k_i, c_i) of a material such that two equal balls of the reference mass
/// (m_eff = m_ref/2, series k_ij = k_i/2) collide with the given behaviour.
struct BallConstants {
  double k;
  double c;
};
BallConstants ball_constants_from_pair(double k_pair, double zeta, double m_ref);
/// k_pair from a contact duration t_c at damping ratio ζ (inverts contact_behaviour's duration).
double pair_stiffness_for_duration(double t_c, double zeta, double m_eff, bool clamp);

}  // namespace silodem::contact
