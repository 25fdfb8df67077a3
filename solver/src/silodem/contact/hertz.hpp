#pragma once
// Hertz normal contact with its viscoelastic damping (docs/model.md §10.3, docs/theory.md §10):
// stateless functions of one pair's overlap and overlap rate, in the sign convention of
// contact_law.hpp (δ > 0 overlap, force > 0 repulsive, δ̇ > 0 approaching).
#include <cmath>

#include "silodem/contact/contact_law.hpp"

namespace silodem::contact {

/// Effective modulus of two elastic spheres, 1/E* = (1−ν_i²)/E_i + (1−ν_j²)/E_j (Johnson 1985, §4.2).
inline double effective_modulus(double e_i, double nu_i, double e_j, double nu_j) {
  return 1.0 / ((1.0 - nu_i * nu_i) / e_i + (1.0 - nu_j * nu_j) / e_j);
}

/// Effective shear modulus, 1/G* = 2(2−ν_i)(1+ν_i)/E_i + 2(2−ν_j)(1+ν_j)/E_j (Mindlin 1949 as used
/// by Chung & Ooi 2011 and LIGGGHTS `tangential_model history` with Hertz).
inline double effective_shear_modulus(double e_i, double nu_i, double e_j, double nu_j) {
  return 1.0 / (2.0 * (2.0 - nu_i) * (1.0 + nu_i) / e_i + 2.0 * (2.0 - nu_j) * (1.0 + nu_j) / e_j);
}

/// Effective radius R* = r_i r_j/(r_i + r_j).
[[gnu::always_inline]] inline double effective_radius(double r_i, double r_j) { return r_i * r_j / (r_i + r_j); }

/// The dashpot constant of the damped Hertz law at overlap δ: c = 2ζ√(m* S_n), S_n = 2E*√(R*δ).
[[gnu::always_inline]] inline double hertz_damping(double e_star, double r_star, double zeta, double m_eff, double delta) {
  return 2.0 * zeta * std::sqrt(m_eff * 2.0 * e_star * std::sqrt(r_star * delta));
}

/// Hertz spring with the viscoelastic dashpot of constant restitution:
/// F = 4/3 E* √R* δ^{3/2} + c δ̇, c = 2ζ √(m* S_n), S_n = 2E*√(R*δ) (the corrected form of seed 003's
/// damping; Tsuji et al. 1992 give the same δ^{1/4} dependence). Elastic energy 8/15 E* √R* δ^{5/2}.
/// `Clamp` as in kelvin_voigt: no tensile force.
template <bool Clamp>
[[gnu::always_inline]] inline PairForce hertz(double e_star, double r_star, double zeta, double m_eff, double delta, double delta_rate) {
  PairForce out;
  const double root = std::sqrt(r_star * delta);  // √(R* δ)
  const double spring = 4.0 / 3.0 * e_star * root * delta;
  out.elastic = 0.4 * spring * delta;
  const double c = hertz_damping(e_star, r_star, zeta, m_eff, delta);
  const double f = spring + c * delta_rate;
  if (Clamp && f < 0.0) {
    out.f = 0.0;
    out.p_dissipated = -spring * delta_rate;
  } else {
    out.f = f;
    out.p_dissipated = c * delta_rate * delta_rate;
  }
  return out;
}

}  // namespace silodem::contact
