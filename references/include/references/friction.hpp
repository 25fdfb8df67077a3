#pragma once
// Closed forms of frictional and Hertz contacts (docs/theory.md §10). Independent of the solver:
// rigid-body impulse balances and Hertz's elastic solution, written from their sources.
#include <algorithm>
#include <cmath>

namespace references {

/// Hertz impact of two elastic spheres (Johnson 1985, §11.4): largest overlap, peak force and
/// duration of a normal impact at relative speed v, effective mass m, radius R and modulus E.
struct HertzImpact {
  double max_overlap, max_force, duration;
};
inline HertzImpact hertz_impact(double m, double r, double e, double v) {
  const double stiffness = 4.0 / 3.0 * e * std::sqrt(r);  // F = K δ^{3/2}
  // ½ m v² = (2/5) K δ_max^{5/2}
  const double d = std::pow(5.0 * m * v * v / (4.0 * stiffness), 0.4);
  // t_c = 2 (δ_max/v) ∫₀¹ dx/√(1 − x^{5/2}); the integral is 1.4716 (Johnson's 2.94/2).
  return {d, stiffness * std::pow(d, 1.5), 2.0 * 1.47161 * d / v};
}

/// A ball thrown along a floor without spin (MFiX DEM-04 type): it slides with deceleration μg
/// while friction spins it up at 5μg/(2R), until v = Rω at t_s = 2u₀/(7μg), then rolls at 5u₀/7.
struct SlipToRoll {
  double slip_time, rolling_speed;
  double speed(double t) const { return t < slip_time ? u0 - mu_g * t : rolling_speed; }
  double spin(double t) const { return (t < slip_time ? mu_g * t : mu_g * slip_time) / (kappa * radius); }
  double u0, mu_g, radius, kappa;
};
/// A ball of inertia κ m r² (2/5 a solid sphere, 1/2 a disc) launched at u0 without spin on a floor
/// with friction μ: it slides, v = u0 − μ g t, ω = μ g t/(κ r), until v = ω r at t_s = κ u0/((1 + κ) μ g),
/// then rolls at u0/(1 + κ) (5/7 u0 for a sphere, 2/3 u0 for a disc).
inline SlipToRoll slip_to_roll(double u0, double mu, double g, double radius, double kappa = 0.4) {
  return {kappa * u0 / ((1.0 + kappa) * mu * g), u0 / (1.0 + kappa), u0, mu * g, radius, kappa};
}

/// Oblique impact of a solid sphere on a fixed plane in gross sliding (Maw, Barber & Fawcett 1976;
/// Chung & Ooi 2011, test 4): incidence θ from the normal at speed V, restitution e, friction μ.
/// Valid when tan θ > 3.5 μ (1 + e): the contact slides throughout.
struct GrossSliding {
  bool applies;
  double tangential_restitution;  // e_t = v_t'/v_t of the centre
  double spin;                     // |ω'| = (5/2)μ(1+e)V cosθ/R, in the sense that rolls the ball forward
                                   // (Chung & Ooi print it negative in their axes)
  double rebound_angle;            // θ_r of the contact point's velocity from the normal, rad
};
inline GrossSliding oblique_gross_sliding(double mu, double e, double theta, double speed, double radius) {
  const double t = std::tan(theta), slide = 3.5 * mu * (1.0 + e);
  return {t > slide, 1.0 - mu * (1.0 + e) / t, 2.5 * mu * (1.0 + e) * speed * std::cos(theta) / radius,
          std::atan((t - slide) / e)};
}

/// A ball spinning in place on a frictionless floor against a constant rolling torque
/// μ_r R F_n = μ_r R m g: ω(t) = ω₀ − 5 μ_r g t / (2R) until it stops.
inline double rolling_spin(double w0, double mu_r, double g, double radius, double t) {
  return std::max(0.0, w0 - 2.5 * mu_r * g * t / radius);
}

/// A ball rolling without slip on a plane (tilted so that gravity has g_t along the roll and g_n
/// into the plane) against a rolling couple μ_r R* F_n, F_n = m g_n: about the contact point
/// (I + m r²) ω̇ = m g_t r − μ_r R* m g_n, so a = (5/7)(g_t − μ_r g_n R*/r) (theory.md §10.5). Started at
/// v₀ ≥ 0 it keeps that acceleration until it stops; it then stays, as it does from rest, when the
/// couple can hold it, g_t ≤ μ_r g_n R*/r.
struct ResistedRolling {
  double v0, accel, hold;  // hold: the largest g_t the couple holds, μ_r g_n R*/r
  double g_t, radius;
  bool held() const { return v0 == 0.0 && g_t <= hold; }
  double speed(double t) const { return held() ? 0.0 : std::max(0.0, v0 + accel * t); }
  double spin(double t) const { return speed(t) / radius; }
};
inline ResistedRolling resisted_rolling(double v0, double g_t, double g_n, double mu_r, double r_star, double radius) {
  const double hold = mu_r * g_n * r_star / radius;
  return {v0, 5.0 / 7.0 * (g_t - hold), hold, g_t, radius};
}

/// The same ball with the couple of an elastic–plastic rolling spring (EPSD; Ai et al. 2011): about the
/// contact point I_c θ̈ + C_r θ̇ + k_r θ = D with D = m g_t r, I_c = I + m r², started at θ = 0,
/// θ̇ = ω₀, a damped oscillator (ζ = C_r/(2√(I_c k_r)) < 1) until the spring k_r |θ| reaches the limit
/// M_m at t₁ — or, `with_dashpot`, spring and dashpot together |k_r θ + C_r θ̇| (LAMMPS's form); from
/// then the couple is M_m against the roll, so ω grows at (D − M_m)/I_c (theory.md §10.5).
/// `limited` is false when the limit is never reached (held).
struct SpringRolling {
  bool limited = false;
  double t1 = 0.0, w1 = 0.0, plastic_rate = 0.0;
  double spin(double t) const { return limited && t > t1 ? w1 + plastic_rate * (t - t1) : NAN; }
};
inline SpringRolling spring_rolling(double w0, double drive, double limit, double k_r, double c_r, double inertia_c,
                                    double until, bool with_dashpot = false) {
  const double omega = std::sqrt(k_r / inertia_c), zeta = c_r / (2.0 * std::sqrt(inertia_c * k_r));
  const double wd = omega * std::sqrt(1.0 - zeta * zeta), theta_s = drive / k_r;
  const double a = -theta_s, b = (w0 + zeta * omega * a) / wd;  // θ − θ_s = e^{−ζΩt}(a cos + b sin)
  const auto theta = [&](double t) {
    return theta_s + std::exp(-zeta * omega * t) * (a * std::cos(wd * t) + b * std::sin(wd * t));
  };
  const auto rate = [&](double t) {
    const double e = std::exp(-zeta * omega * t), c = std::cos(wd * t), s = std::sin(wd * t);
    return e * ((b * wd - zeta * omega * a) * c - (a * wd + zeta * omega * b) * s);
  };
  const auto held = [&](double t) { return std::abs(k_r * theta(t) + (with_dashpot ? c_r * rate(t) : 0.0)); };
  SpringRolling out;
  const double step = 1e-3 / omega;  // a thousandth of a radian of the oscillation
  double lo = 0.0;
  for (double t = step; t <= until; t += step) {
    if (held(t) < limit) { lo = t; continue; }
    double hi = t;
    for (int k = 0; k < 100; ++k) {
      const double mid = 0.5 * (lo + hi);
      (held(mid) < limit ? lo : hi) = mid;
    }
    out.limited = true;
    out.t1 = hi;
    out.w1 = rate(hi);
    out.plastic_rate = (drive - std::copysign(limit, theta(hi))) / inertia_c;
    return out;
  }
  return out;
}

/// A ball on a plane whose contact resists slip viscously, F = −γ s with s = v − a ω the slip of
/// its surface (a the lever arm to the contact point, I its moment of inertia): F moves v by F/m
/// and ω by −a F/I, so s decays as s₀ e^{−t/τ}, τ = m_t/γ with 1/m_t = 1/m + a²/I, and the angular
/// momentum about the contact point, m a v + I ω, stays. Thrown at u₀ without spin, it ends rolling
/// at (1 − m_t/m) u₀ = 5u₀/7 (solid sphere, a = R), as in slip to roll, but smoothly.
struct ViscousSlip {
  double u0, tau, slip_mass, mass, arm, inertia;
  double speed(double t) const { return u0 - slip_mass / mass * u0 * (1.0 - std::exp(-t / tau)); }
  double spin(double t) const { return arm * slip_mass / inertia * u0 * (1.0 - std::exp(-t / tau)); }
};
inline ViscousSlip viscous_slip(double u0, double gamma, double mass, double inertia, double arm) {
  const double slip_mass = 1.0 / (1.0 / mass + arm * arm / inertia);
  return {u0, slip_mass / gamma, slip_mass, mass, arm, inertia};
}

/// The same ball held by a sticking tangential spring k_t (undamped), started with slip s₀ and no
/// angular momentum about the contact point, m a v + I ω = 0: only the slip mode moves, at
/// ω_t = √(k_t/m_t), s = s₀ cos ω_t t, v = (m_t/m) s, ω = −(a m_t/I) s. For a = R, m_t = 2m/7.
struct StickingSlip {
  double s0, omega_t, slip_mass, mass, arm, inertia;
  double slip(double t) const { return s0 * std::cos(omega_t * t); }
  double speed(double t) const { return slip_mass / mass * slip(t); }
  double spin(double t) const { return -arm * slip_mass / inertia * slip(t); }
};
inline StickingSlip sticking_slip(double s0, double k_t, double mass, double inertia, double arm) {
  const double slip_mass = 1.0 / (1.0 / mass + arm * arm / inertia);
  return {s0, std::sqrt(k_t / slip_mass), slip_mass, mass, arm, inertia};
}

}  // namespace references
