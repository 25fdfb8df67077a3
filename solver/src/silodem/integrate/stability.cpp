#include "silodem/integrate/stability.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

namespace silodem {

// The limits below are the spectral radius = 1 crossings of each scheme's amplification matrix on
// ü = −ω0² u − 2ζω0 u̇ (computed for ζ in [0, 3], and for 1 to 1000 corrector passes), written in
// the closed forms they match; tests/solver/integrate/stability_test.cpp runs the schemes across them.
double midpoint_spectral_radius(double Omega, double zeta) {
  const std::complex<double> root = std::sqrt(std::complex<double>(zeta * zeta - 1.0, 0.0));
  double rho = 0.0;
  for (const std::complex<double> z : {Omega * (-zeta + root), Omega * (-zeta - root)})
    rho = std::max(rho, std::abs(1.0 + z + 0.5 * z * z));
  return rho;
}

namespace {

/// The first Ω > 0 where the midpoint scheme's spectral radius passes 1 (0 when it is above 1 from
/// the start): scanned in steps of 0.1 % and refined by bisection.
double midpoint_omega_limit(double zeta) {
  if (!(zeta > 0.0)) return 0.0;
  double lo = 1e-9, hi = lo;
  while (hi < 1e3 && midpoint_spectral_radius(hi, zeta) <= 1.0) lo = hi, hi *= 1.001;
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    (midpoint_spectral_radius(mid, zeta) <= 1.0 ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace

std::pair<double, double> midpoint_viscosity_window(double omega, double zeta, double dt) {
  const auto stable = [&](double mu) { return midpoint_spectral_radius(omega * dt, zeta + mu / (2.0 * omega)) <= 1.0; };
  // A stable μ, if any: the window's lower end grows as ω⁴Δt³/4 and its upper end is about 2/Δt.
  double inside = NAN;
  for (double mu_dt = 1e-12; mu_dt < 10.0 && std::isnan(inside); mu_dt *= 1.01)
    if (stable(mu_dt / dt)) inside = mu_dt / dt;
  if (std::isnan(inside)) return {NAN, NAN};
  const auto edge = [&](double in, double out) {
    for (int k = 0; k < 100; ++k) {
      const double mid = 0.5 * (in + out);
      (stable(mid) ? in : out) = mid;
    }
    return in;
  };
  const double lo = stable(0.0) ? 0.0 : edge(inside, 0.0);
  return {lo, edge(inside, 100.0 / dt)};
}

StabilityLimit stable_time_step(const IntegratorSpec& in, double omega0, double zeta) {
  if (in.scheme == Scheme::RungeKuttaMidpoint) {
    // The viscosity damps every relative motion as it damps each ball's: ζ + μ/(2ω0). A free ball's
    // velocity decays by the real root −μ, stable while μΔt ≤ 2.
    const double limit = midpoint_omega_limit(zeta + in.viscosity / (2.0 * omega0)) / omega0;
    if (in.viscosity > 0.0 && 2.0 / in.viscosity < limit) return {2.0 / in.viscosity, "2/mu (a free ball's decay)"};
    return {limit, in.viscosity > 0.0 || zeta > 0.0
                       ? "the midpoint scheme's spectral radius on w0 with zeta + mu/(2 w0) (docs/theory.md §7.8)"
                       : "none: the midpoint scheme grows every undamped oscillation; give \"viscosity\" (docs/theory.md §7.8)"};
  }
  if (in.scheme == Scheme::VelocityVerlet) {
    if (in.half_step_dashpot)  // the central-difference limit with a lagged dashpot
      return {2.0 / omega0 * (std::sqrt(1.0 + zeta * zeta) - zeta), "2/w0 (sqrt(1 + zeta^2) - zeta)"};
    // The predicted velocity v½ + ½Δt·ü_n extrapolates the dashpot force, which doubles its
    // destabilising weight.
    return {2.0 / omega0 * (std::sqrt(1.0 + 4.0 * zeta * zeta) - 2.0 * zeta),
            "2/w0 (sqrt(1 + 4 zeta^2) - 2 zeta)"};
  }
  // The explicit form is exactly the undamped central-difference limit at ζ = 0, and damping only
  // lowers it, so 2/ω0 refuses nothing stable. More passes converge towards the linear-acceleration
  // scheme, whose fixed-point corrector diverges once (ω0Δt)²/6 > 1; below that bound their limit
  // is irregular in the pass count (1.16/ω0 to 2.26/ω0 undamped), so only the certain bound is used.
  if (in.max_corrector_passes == 1) return {2.0 / omega0, "2/w0"};
  return {std::sqrt(6.0) / omega0, "sqrt(6)/w0 (the corrector passes diverge beyond it)"};
}

// docs/theory.md §7.7. With the half-step velocity the spring increment v½Δt is the scheme's own
// position update, so the normal-mode limit holds. The predicted velocity v_n + Δt ü_n puts
// Δt² ü_n into the spring instead of ½Δt² ü_n: a root leaves through −1 at Ω² + 4ζΩ = 2. The
// predictor–corrector grows the spring by Δt v⁽ʲ⁾ each pass, which maps a velocity error by
// −g, g = Ω²/2 + ζΩ: odd pass counts leave through +1 at g = 1, even ones a little above it except
// at ζ = 0, so g = 1 bounds every count the stop test can end at.
StabilityLimit stable_tangential_time_step(const IntegratorSpec& in, double omega_t, double zeta_t) {
  // Not derived for the midpoint scheme's spring update: its normal-mode limit stands in for it.
  if (in.scheme == Scheme::RungeKuttaMidpoint) return stable_time_step(in, omega_t, zeta_t);
  if (in.scheme == Scheme::VelocityVerlet && in.half_step_dashpot) return stable_time_step(in, omega_t, zeta_t);
  if (in.scheme == Scheme::VelocityVerlet)
    return {(std::sqrt(2.0 + 4.0 * zeta_t * zeta_t) - 2.0 * zeta_t) / omega_t, "(sqrt(2 + 4 zeta_t^2) - 2 zeta_t)/w_t"};
  return {(std::sqrt(2.0 + zeta_t * zeta_t) - zeta_t) / omega_t,
          "(sqrt(2 + zeta_t^2) - zeta_t)/w_t (the corrector passes diverge beyond it)"};
}

}  // namespace silodem
