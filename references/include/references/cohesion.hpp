#pragma once
// Escape from the cohesion zone (docs/theory.md §2a): a free pair separating at u0 from δ = 0 feels
// −k s in the zone 0 ≤ s ≤ |δ_c| and nothing beyond. Escape iff u0 > v* = ω_c|δ_c| = N_max/√(k m_eff);
// then it leaves at √(u0² − v*²); otherwise it turns at the gap u0/ω_c.
#include <cmath>

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

}  // namespace references
