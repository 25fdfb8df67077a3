#pragma once
// The restitution of the damped Hertz contact (contact/hertz.hpp) and its inverse. With the
// dashpot c = 2ζ√(m* S_n), S_n = 2E*√(R*δ), the contact scales out: in δ = L x, t = (L/v₀) τ with
// L = (m* v₀² / (4/3 E*√R*))^{2/5} its equation is ẍ = −x^{3/2} − 2√(3/2) ζ x^{1/4} ẋ, x(0) = 0,
// ẋ(0) = 1, whatever the impact speed: e depends on ζ alone (docs/theory.md §10.2). No closed
// form is known; it is integrated here once, with RK4 at a step far below any DEM step.
namespace silodem::contact {

/// e of the damped Hertz contact at damping ratio ζ; `clamp`: the contact ends when the force
/// does (no tension), else when the overlap does.
double hertz_restitution(double zeta, bool clamp);

/// ζ giving restitution e ∈ (0, 1] (bisection on hertz_restitution, to 1e-10 of ζ).
double hertz_damping_ratio_for_restitution(double e, bool clamp);

/// Duration of an undamped Hertz impact at speed v: 2.868 (m*² / (R* E*² v))^{1/5}
/// (Johnson 1985, §11.4: t_c = 2.9432 δ_max/v with δ_max = (15 m* v² / (16 E* √R*))^{2/5}).
double hertz_contact_time(double m_eff, double r_star, double e_star, double speed);

/// The stiffest moment of an undamped Hertz impact at approach speed v: the largest overlap
/// δ_max = (15 m* v² / (16 E* √R*))^{2/5} (energy balance) and the tangent stiffness there,
/// k_max = dF/dδ = 2E*√(R* δ_max), with ω_max = √(k_max/m*) = √(15/8) v/δ_max (docs/theory.md §10.9).
struct HertzPeak {
  double overlap = 0.0;    // δ_max, m
  double stiffness = 0.0;  // k_max, N/m
  double omega = 0.0;      // ω_max, rad/s
};
HertzPeak hertz_peak(double m_eff, double r_star, double e_star, double speed);

}  // namespace silodem::contact
