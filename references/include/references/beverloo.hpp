#pragma once
// Discharge rate through a circular orifice (docs/theory.md §6): Beverloo et al., Chem. Eng. Sci. 15
// (1961) 260, W = C ρ_b √g (D_0 − k d)^{5/2}, with C ≈ 0.58 and k ≈ 1.5 for spheres (frictional;
// for frictionless hard spheres docs/theory.md §6 expects C somewhat higher, 0.6–0.75 — an inference).
#include <cmath>
#include <vector>

namespace references {

inline double beverloo_mass_flow(double rho_bulk, double g, double outlet, double grain_d, double C = 0.58,
                                 double k = 1.5) {
  const double a = outlet - k * grain_d;
  return a > 0.0 ? C * rho_bulk * std::sqrt(g) * std::pow(a, 2.5) : 0.0;
}

/// Steady mass flow from exit times and masses inside [t0, t1]: the least-squares slope of the
/// cumulative mass, and its uncertainty as the standard error of the rates of `blocks` equal
/// sub-windows.
struct FlowRate {
  double rate = 0.0, uncertainty = 0.0;
  std::size_t exits = 0;
};
inline FlowRate steady_flow(const std::vector<double>& t, const std::vector<double>& mass, double t0, double t1,
                            int blocks = 5) {
  FlowRate f;
  double cum = 0.0, st = 0.0, sm = 0.0, stt = 0.0, stm = 0.0;
  std::vector<double> block_mass(std::size_t(blocks), 0.0);
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] < t0 || t[i] > t1) continue;
    cum += mass[i];
    ++f.exits;
    st += t[i], sm += cum, stt += t[i] * t[i], stm += t[i] * cum;
    const int b = std::min(blocks - 1, int((t[i] - t0) / (t1 - t0) * blocks));
    block_mass[std::size_t(b)] += mass[i];
  }
  const double n = double(f.exits);
  if (f.exits < 2) return f;
  f.rate = (n * stm - st * sm) / (n * stt - st * st);
  double mean = 0.0, var = 0.0;
  const double dt = (t1 - t0) / blocks;
  for (double m : block_mass) mean += m / dt / blocks;
  for (double m : block_mass) var += (m / dt - mean) * (m / dt - mean) / (blocks - 1);
  f.uncertainty = std::sqrt(var / blocks);
  return f;
}

}  // namespace references
