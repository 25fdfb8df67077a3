#include "silodem/contact/pair_constants.hpp"

#include <cmath>
#include <stdexcept>

#include "silodem/core/types.hpp"

namespace silodem::contact {

double cohesion_reach(double p_n, double g_abs, double m_min, double k_ij) {
  // (10): the printed reach N_max/k with N_max = p_N · weight of the lighter ball.
  return -p_n * g_abs * m_min / k_ij;
}

namespace {
// Dimensionless duration ω0·t_c and restitution for damping ratio ζ (docs/theory.md §1a, §1b).
void dimensionless(double zeta, bool clamp, double& w0t, double& e) {
  if (!clamp) {
    if (zeta >= 1.0) {  // overdamped unclamped: the overlap never returns to zero
      w0t = INFINITY;
      e = 0.0;
      return;
    }
    const double s = std::sqrt(1.0 - zeta * zeta);
    w0t = kPi / s;
    e = std::exp(-kPi * zeta / s);
    return;
  }
  if (zeta < 1.0) {
    const double s = std::sqrt(1.0 - zeta * zeta);     // ω/ω0
    const double phase = kPi - 2.0 * std::atan(zeta / s);  // ω t* (§1b)
    w0t = phase / s;
    e = std::exp(-(zeta / s) * phase);
  } else if (zeta == 1.0) {
    w0t = 2.0;  // critically damped: force vanishes at ω0 t = 2 (limit of the formula below)
    e = std::exp(-2.0);
  } else {
    const double so = std::sqrt(zeta * zeta - 1.0);  // Ω_o/ω0
    w0t = std::log((zeta + so) / (zeta - so)) / so;
    e = std::pow((zeta - so) / (zeta + so), zeta / so);
  }
}
}  // namespace

ContactBehaviour contact_behaviour(double k, double c, double m_eff, bool clamp) {
  ContactBehaviour b{};
  b.omega0 = std::sqrt(k / m_eff);
  b.zeta = c / (2.0 * std::sqrt(k * m_eff));
  double w0t = 0.0;
  dimensionless(b.zeta, clamp, w0t, b.restitution);
  b.duration = w0t / b.omega0;
  return b;
}

double damping_ratio_for_restitution(double e, bool clamp) {
  if (!(e > 0.0 && e <= 1.0)) throw std::invalid_argument("restitution must be in (0, 1]");
  if (e == 1.0) return 0.0;
  if (!clamp) {
    const double l = std::log(e);
    return -l / std::sqrt(kPi * kPi + l * l);
  }
  // Clamped e(ζ) falls monotonically from 1 to 0 as ζ → ∞; bracket and bisect.
  double lo = 0.0, hi = 1.0, w0t = 0.0, eh = 0.0;
  for (dimensionless(hi, true, w0t, eh); eh > e; dimensionless(hi, true, w0t, eh)) hi *= 2.0;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    double em = 0.0;
    dimensionless(mid, true, w0t, em);
    (em > e ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

BallConstants ball_constants_from_pair(double k_pair, double zeta, double m_ref) {
  const double m_eff = 0.5 * m_ref;
  const double c_pair = 2.0 * zeta * std::sqrt(k_pair * m_eff);
  // Two equal balls in series (11): k_pair = k_i/2, c_pair = c_i/2.
  return {2.0 * k_pair, 2.0 * c_pair};
}

double pair_stiffness_for_duration(double t_c, double zeta, double m_eff, bool clamp) {
  double w0t = 0.0, e = 0.0;
  dimensionless(zeta, clamp, w0t, e);
  if (!std::isfinite(w0t)) throw std::invalid_argument("no finite contact time for this damping ratio");
  const double omega0 = w0t / t_c;
  return m_eff * omega0 * omega0;
}

}  // namespace silodem::contact
