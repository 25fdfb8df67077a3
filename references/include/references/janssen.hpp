#pragma once
// Janssen (1895) and EN 1991-4 filling pressures (docs/theory.md §4, §5), and the two-parameter fit
// DEM studies use to extract K and μ_w from a wall-pressure profile.
#include <cmath>
#include <vector>

namespace references {

/// Horizontal wall pressure at depth z below the surface of a cylinder of diameter D filled with a
/// bulk of unit weight γ = ρ_b g: p_h = (γ D / 4μ_w)(1 − exp(−4 K μ_w z / D)).
inline double janssen_pressure(double gamma, double D, double K, double mu_w, double z) {
  return gamma * D / (4.0 * mu_w) * (1.0 - std::exp(-4.0 * K * mu_w * z / D));
}

/// EN 1991-4 §5.2.1 (slender silo, filling): p_hf = p_ho Y_J(z), p_ho = γ K z_o, z_o = A/(K μ U) —
/// the same curve as Janssen written in the code's symbols; K = K_m = 1.1 (1 − sin φ_im) when φ_im
/// is given instead of K (docs/theory.md §5).
inline double en1991_4_filling_pressure(double gamma, double D, double K, double mu, double z) {
  const double z_o = D / (4.0 * K * mu), p_ho = gamma * K * z_o;
  return p_ho * (1.0 - std::exp(-z / z_o));
}
inline double en1991_4_K(double phi_im) { return 1.1 * (1.0 - std::sin(phi_im)); }
/// dK_m/dφ_im of the same conversion, −1.1 cos φ_im: carries a scatter of φ_im into K.
inline double en1991_4_dK_dphi(double phi_im) { return -1.1 * std::cos(phi_im); }

struct JanssenFit {
  double p_ho = 0.0;   // saturation pressure γD/(4μ_w)
  double z_o = 0.0;    // Janssen length D/(4Kμ_w)
  double r2 = 0.0;     // coefficient of determination of the fit
  double rms = 0.0;    // rms residual
};

/// Least-squares fit of p(z) = p_ho (1 − exp(−z/z_o)): for a given z_o the best p_ho is linear,
/// so the fit is a one-dimensional search over z_o (golden section on log z_o).
inline JanssenFit fit_janssen(const std::vector<double>& z, const std::vector<double>& p) {
  const auto best_for = [&](double zo, JanssenFit& f) {
    double sxy = 0.0, sxx = 0.0;
    for (std::size_t i = 0; i < z.size(); ++i) {
      const double x = 1.0 - std::exp(-z[i] / zo);
      sxy += x * p[i];
      sxx += x * x;
    }
    f.z_o = zo;
    f.p_ho = sxx > 0.0 ? sxy / sxx : 0.0;
    double ss = 0.0;
    for (std::size_t i = 0; i < z.size(); ++i) {
      const double r = p[i] - f.p_ho * (1.0 - std::exp(-z[i] / zo));
      ss += r * r;
    }
    return ss;
  };
  double zmax = 0.0;
  for (double v : z) zmax = std::max(zmax, v);
  double lo = std::log(zmax * 1e-3), hi = std::log(zmax * 1e3);
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  JanssenFit f;
  for (int it = 0; it < 200; ++it) {
    const double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
    JanssenFit fa, fb;
    if (best_for(std::exp(a), fa) < best_for(std::exp(b), fb)) hi = b;
    else lo = a;
  }
  const double ss = best_for(std::exp(0.5 * (lo + hi)), f);
  double mean = 0.0, tot = 0.0;
  for (double v : p) mean += v / double(p.size());
  for (double v : p) tot += (v - mean) * (v - mean);
  f.r2 = tot > 0.0 ? 1.0 - ss / tot : 1.0;
  f.rms = std::sqrt(ss / double(p.size()));
  return f;
}

}  // namespace references
