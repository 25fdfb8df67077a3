#include "silodem/integrate/stability.hpp"

#include <cmath>

namespace silodem {

// The limits below are the spectral radius = 1 crossings of each scheme's amplification matrix on
// ü = −ω0² u − 2ζω0 u̇ (computed for ζ in [0, 3], and for 1 to 1000 corrector passes), written in
// the closed forms they match; tests/solver/integrate/stability_test.cpp runs the schemes across them.
StabilityLimit stable_time_step(const IntegratorSpec& in, double omega0, double zeta) {
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
  if (in.scheme == Scheme::VelocityVerlet && in.half_step_dashpot) return stable_time_step(in, omega_t, zeta_t);
  if (in.scheme == Scheme::VelocityVerlet)
    return {(std::sqrt(2.0 + 4.0 * zeta_t * zeta_t) - 2.0 * zeta_t) / omega_t, "(sqrt(2 + 4 zeta_t^2) - 2 zeta_t)/w_t"};
  return {(std::sqrt(2.0 + zeta_t * zeta_t) - zeta_t) / omega_t,
          "(sqrt(2 + zeta_t^2) - zeta_t)/w_t (the corrector passes diverge beyond it)"};
}

}  // namespace silodem
