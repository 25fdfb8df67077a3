#pragma once
// Closed forms of a linear spring–dashpot binary collision (docs/theory.md §1, Schwager & Pöschel,
// Granular Matter 9 (2007) 465). Written independently of the solver's own contact_behaviour():
// the clamped case uses the original piecewise arctan form, not the solver's compact one.
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace references {

struct Collision {
  double restitution;
  double duration;
  double zeta;
  double omega0;
};

/// Head-on collision of a pair with stiffness k, dashpot c and effective mass m_eff, no gravity.
/// Unclamped (docs/theory.md §1a): the contact ends when the overlap returns to zero, e = exp(−πζ/√(1−ζ²)),
/// t_c = π/ω. Clamped (§1b): it ends when k δ + c δ̇ = 0.
inline Collision kelvin_voigt_collision(double k, double c, double m_eff, bool clamp) {
  using std::numbers::pi;
  const double w0 = std::sqrt(k / m_eff), beta = c / (2.0 * m_eff), zeta = beta / w0;
  if (zeta >= 1.0) {
    if (!clamp) throw std::domain_error("unclamped overdamped contact never ends");
    if (zeta == 1.0) return {std::exp(-2.0), 2.0 / w0, zeta, w0};
    const double wo = std::sqrt(beta * beta - w0 * w0);
    return {std::pow((beta - wo) / (beta + wo), beta / wo), std::log((beta + wo) / (beta - wo)) / wo, zeta, w0};
  }
  const double w = std::sqrt(w0 * w0 - beta * beta);
  if (!clamp) return {std::exp(-beta * pi / w), pi / w, zeta, w0};
  // Force-zero end: tan(ω t*) = −2βω/(ω² − β²), taken on the branch in (0, π) — Schwager & Pöschel eq. (15).
  double wt = std::atan(-2.0 * beta * w / (w * w - beta * beta));
  if (w * w - beta * beta > 0.0) wt += pi;           // ζ < 1/√2: the angle lies in (π/2, π)
  else if (w * w == beta * beta) wt = pi / 2.0;
  return {std::exp(-beta * wt / w), wt / w, zeta, w0};
}

/// The same collision integrated by a scheme whose dashpot sees the velocity half a step late
/// (velocity Verlet as in LAMMPS's fix nve/sphere and LIGGGHTS, YADE's leapfrog; docs/theory.md
/// §1d): c v(t − Δt/2) ≈ c v(t) − ½ c Δt a, so m a = −k δ − c v + ½ c Δt a, i.e. the exact
/// law with the inertia m_eff − c Δt/2 (ζ → ζ/√(1 − ζΩ)). At ζ = 0.9, Ω = 0.063 this predicts
/// Δe/e = −0.71 unclamped against measured −0.74, and −0.037 clamped (the solver's onset-corrected
/// runs land within 0.2 % of it: tests/harness/checks_test.cpp); the remainder stays within
/// scheme_error_bound().
inline Collision kelvin_voigt_collision_lagged(double k, double c, double m_eff, bool clamp, double dt) {
  return kelvin_voigt_collision(k, c, m_eff - 0.5 * c * dt, clamp);
}

/// Error bound every plain scheme meets on one collision, Ω = Δt·√(k/m_eff):
///   |Δe/e| ≤ 3ζΩ + Ω²/8 + 0.5Ω³.
/// (docs/theory.md §8.3). 3ζΩ: the dashpot force jumps by c·v0 at first touch, which the step grid
/// sees up to one step late. Ω²/8: the elastic force is continuous at touch but
/// its slope is not, and a contact that starts and ends at arbitrary phases of the step grid
/// loses or gains up to Ω²/8 (measured sup over phases and non-integer t_c/Δt for velocity
/// Verlet and the predictor–corrector: 0.96–1.04 × Ω²/8 at t_c/Δt = 25…100); elastic errors
/// measured at integer t_c/Δt (1.6e-5 at 50) miss it, because there the onset and end phases
/// cancel.
inline double scheme_error_bound(double zeta, double omega_dt) {
  return 3.0 * zeta * omega_dt + omega_dt * omega_dt / 8.0 + 0.5 * omega_dt * omega_dt * omega_dt;
}

/// A ball hitting a fixed ball under gravity with normal component g_n (pointing into the contact):
/// m δ̈ + c δ̇ + k δ = m g_n, δ(0) = 0, δ̇(0) = v0 (docs/theory.md §1c). The exact δ(t) is closed form;
/// the end of contact (δ = 0, or force = 0 when clamped) is found by bracketing and bisection.
/// Returns the rebound restitution e_g = −δ̇(t_end)/v0 (0 if the ball comes to rest).
inline double restitution_with_gravity(double k, double c, double m, double v0, double g_n, bool clamp) {
  const double w0 = std::sqrt(k / m), beta = c / (2.0 * m);
  if (beta >= w0) throw std::domain_error("restitution_with_gravity: underdamped contacts only");
  const double w = std::sqrt(w0 * w0 - beta * beta), ds = g_n / (w0 * w0);
  const double B = (v0 - beta * ds) / w;
  auto delta = [&](double t) { return ds + std::exp(-beta * t) * (-ds * std::cos(w * t) + B * std::sin(w * t)); };
  auto rate = [&](double t) {
    const double ex = std::exp(-beta * t);
    return -beta * ex * (-ds * std::cos(w * t) + B * std::sin(w * t)) + ex * (ds * w * std::sin(w * t) + B * w * std::cos(w * t));
  };
  auto ended = [&](double t) { return clamp ? k * delta(t) + c * rate(t) <= 0.0 : delta(t) <= 0.0; };
  // March in steps of a small fraction of the period to bracket the first end, then bisect.
  const double h = 1e-3 * std::numbers::pi / w;
  double t0 = h, t1 = 0.0;
  for (int i = 0; i < 20000; ++i, t0 += h) {
    if (ended(t0)) {
      t1 = t0;
      t0 -= h;
      break;
    }
  }
  if (t1 == 0.0) return 0.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (t0 + t1);
    (ended(mid) ? t1 : t0) = mid;
  }
  return -rate(t1) / v0;
}

}  // namespace references
