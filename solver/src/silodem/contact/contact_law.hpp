#pragma once
// The paper's interaction law (Algorithm 1) as small stateless functions of one pair's overlap
// and overlap rate. The force loop combines them once per scene (forces/force_field.hpp); tests
// check each against closed forms. Sign convention (docs/model.md §2.1): delta > 0 is overlap, the
// scalar force is positive when repulsive and acts on ball i along n_ij = (u_i - u_j)/|u_i - u_j|.

namespace silodem::contact {

/// What one pair contributes: the scalar force along n_ij and the energy terms of the ledger.
struct PairForce {
  double f = 0.0;           // on i along n_ij, > 0 repulsive
  double elastic = 0.0;     // energy stored in the spring now: ½ k δ²
  double p_dissipated = 0.0;// dashpot power removed from the system (≥ 0)
  double p_cohesion = 0.0;  // power flowing into an active cohesion spring (≥ 0)
};

/// Overlap (5): δ = r_i + r_j − |u_i − u_j|.
inline double overlap(double r_i, double r_j, double distance) { return r_i + r_j - distance; }

/// Kelvin–Voigt body (4) for δ > 0. `delta_rate` is dδ/dt = −(u̇_i − u̇_j)·n_ij, positive while the
/// pair approaches — docs/model.md §2.2 Reading: the printed δ̇ⁿ (7) has the opposite sign, and with it
/// the dashpot would push approaching balls together (e > 1).
/// `Clamp`: the force is not allowed to become tensile (YADE's law, LAMMPS `limit_damping`);
/// the paper's law (Clamp = false) lets the dashpot pull late in a damped contact.
template <bool Clamp>
[[gnu::always_inline]] inline PairForce kelvin_voigt(double k, double c, double delta, double delta_rate) {
  PairForce out;
  out.elastic = 0.5 * k * delta * delta;
  const double f = k * delta + c * delta_rate;
  if (Clamp && f < 0.0) {
    // The whole force vanishes: the spring energy released while δ shrinks is lost, not returned.
    out.f = 0.0;
    out.p_dissipated = -k * delta * delta_rate;
  } else {
    out.f = f;
    out.p_dissipated = c * delta_rate * delta_rate;
  }
  return out;
}

/// Cohesion zone (9)(10) for δ_c ≤ δ ≤ 0: a Hookean tensile spring f = k δ, acting only while the
/// pair separates (delta_rate < 0). docs/model.md §2.3 Reading: the printed condition d < 0 and (9)
/// disagree in sign; cohesion acts on separation only, so approach inside the zone is force-free.
/// `delta_c` is negative (the reach, (10)).
inline PairForce cohesion(double k, double delta_c, double delta, double delta_rate) {
  PairForce out;
  if (delta >= delta_c && delta_rate < 0.0) {
    out.f = k * delta;
    out.elastic = 0.5 * k * delta * delta;
    out.p_cohesion = k * delta * delta_rate;  // both negative: energy flows into the spring
  }
  return out;
}

/// The paper's law for a pair apart by −δ: zero beyond the reach δ_c (10) of the lighter ball's
/// weight p_N |g| m_min, the cohesion spring (9) within it. Shared by every law that has cohesion.
[[gnu::always_inline]] inline PairForce cohesion_zone(double k, double pn_g, double m_min, double delta, double delta_rate) {
  const double delta_c = -pn_g * m_min / k;  // (10), as cohesion_reach(1, p_N|g|, m_min, k)
  if (delta < delta_c) return {};
  return cohesion(k, delta_c, delta, delta_rate);  // (9)
}

}  // namespace silodem::contact
