// The Janssen fit on synthetic profiles with known parameters, and the Janssen and EN 1991-4
// pressures against the slice balance they solve.
#include <gtest/gtest.h>

#include <cmath>

#include "references/janssen.hpp"

using namespace references;

TEST(JanssenFit, RecoversKnownParameters) {
  const double gamma = 15000.0, D = 0.1, K = 0.9, mu = 0.2;
  std::vector<double> z, p;
  for (int i = 1; i <= 30; ++i) {
    z.push_back(0.02 * i);
    // ±1 % deterministic scatter.
    p.push_back(janssen_pressure(gamma, D, K, mu, z.back()) * (1.0 + 0.01 * std::sin(7.0 * i)));
  }
  const JanssenFit f = fit_janssen(z, p);
  EXPECT_NEAR(f.p_ho, gamma * D / (4 * mu), 0.03 * gamma * D / (4 * mu));
  EXPECT_NEAR(f.z_o, D / (4 * K * mu), 0.05 * D / (4 * K * mu));
  EXPECT_GT(f.r2, 0.99);
}

TEST(JanssenFit, ExactDataExactFit) {
  std::vector<double> z{0.1, 0.2, 0.4, 0.8, 1.6}, p;
  for (double x : z) p.push_back(1000.0 * (1.0 - std::exp(-x / 0.35)));
  const JanssenFit f = fit_janssen(z, p);
  EXPECT_NEAR(f.p_ho, 1000.0, 1e-3);
  EXPECT_NEAR(f.z_o, 0.35, 1e-6);
  EXPECT_NEAR(f.r2, 1.0, 1e-12);
}

// The slice balance Janssen solved, dσ_v/dz = γ − (4 μ_w K / D) σ_v with σ_v(0) = 0 and p_h = K σ_v,
// integrated here by classical Runge–Kutta: the closed forms (Janssen's and EN 1991-4's) must be
// its solution at every depth, and keep its two limits — hydrostatic K γ z near the surface and the
// saturation γ D/(4 μ_w), which does not depend on K, deep down.
TEST(JanssenPressure, SolvesTheSliceBalance) {
  const double gamma = 9000.0, D = 5.0, mu = 0.38;  // wheat on smooth steel, a 5 m silo (EN 1991-4 Annex E)
  for (const double K : {0.54, 0.9}) {
    const auto rate = [&](double sigma) { return gamma - 4.0 * mu * K / D * sigma; };
    double sigma = 0.0, z = 0.0;
    const double h = 0.001;
    for (int n = 1; n <= 80000; ++n) {  // to 80 m, 13 Janssen lengths at K = 0.54
      const double k1 = rate(sigma), k2 = rate(sigma + 0.5 * h * k1), k3 = rate(sigma + 0.5 * h * k2),
                   k4 = rate(sigma + h * k3);
      sigma += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
      z = n * h;
      if (n % 5000 == 0) {
        EXPECT_NEAR(janssen_pressure(gamma, D, K, mu, z) / (K * sigma), 1.0, 1e-9) << "K " << K << ", z " << z;
        EXPECT_NEAR(en1991_4_filling_pressure(gamma, D, K, mu, z) / (K * sigma), 1.0, 1e-9) << "K " << K << ", z " << z;
      }
    }
    // Deep: saturated at γ D/(4 μ_w) whatever K.
    EXPECT_NEAR(janssen_pressure(gamma, D, K, mu, z) / (gamma * D / (4.0 * mu)), 1.0, 1e-5) << K;
    // Shallow: hydrostatic, p_h/(K γ z) = 1 − x/2 + x²/6 − O(x³), x = z/z_o, z_o = D/(4 K μ_w).
    const double z_small = 0.01, x = z_small * 4.0 * K * mu / D;
    EXPECT_NEAR(janssen_pressure(gamma, D, K, mu, z_small) / (K * gamma * z_small), 1.0 - x / 2.0 + x * x / 6.0, 1e-9);
  }
}

TEST(En1991_4, LateralRatioAgainstTheStandardsTable) {
  // EN 1991-4 Annex E, Table E.1, wheat: φ_im = 30°, K_m = 0.54, given to two decimals from
  // measurements; the formula K_m = 1.1(1 − sin φ_im) of §4.2.2 gives 0.55 (docs/theory.md §5).
  EXPECT_NEAR(en1991_4_K(30.0 * M_PI / 180.0), 0.54, 0.015);
  // A larger angle of internal friction holds more of the load: K_m falls.
  EXPECT_LT(en1991_4_K(36.0 * M_PI / 180.0), en1991_4_K(30.0 * M_PI / 180.0));
}

TEST(En1991_4, TheSlopeOfTheConversionIsItsCentralDifference) {
  // The slope that carries a scatter of φ_im into K, against the conversion's own central
  // difference (truncation 1.1 h²/6 ≈ 2e-13 at h = 1e-6 rad, rounding about 1e-10).
  for (const double deg : {20.0, 25.4, 36.0}) {
    const double phi = deg * M_PI / 180.0, h = 1e-6;
    const double central = (en1991_4_K(phi + h) - en1991_4_K(phi - h)) / (2.0 * h);
    EXPECT_NEAR(en1991_4_dK_dphi(phi), central, 1e-8) << deg;
  }
}

#include "references/beverloo.hpp"

TEST(Beverloo, FormulaAndSteadyRate) {
  // W = 0.58 · 1500 · √9.81 · (0.05 − 1.5·0.005)^{5/2}
  EXPECT_NEAR(beverloo_mass_flow(1500, 9.81, 0.05, 0.005), 0.58 * 1500 * std::sqrt(9.81) * std::pow(0.0425, 2.5),
              1e-12);
  EXPECT_EQ(beverloo_mass_flow(1500, 9.81, 0.005, 0.005), 0.0);  // orifice below k d: no flow
  // Exits every 2 ms of 1 g each: 0.5 kg/s, no scatter between blocks.
  std::vector<double> t, m;
  for (int i = 0; i < 500; ++i) t.push_back(0.002 * i), m.push_back(0.001);
  const FlowRate f = steady_flow(t, m, 0.1, 0.9);
  EXPECT_NEAR(f.rate, 0.5, 1e-9);
  EXPECT_LT(f.uncertainty, 0.02 * 0.5);
}
