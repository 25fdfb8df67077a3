// The Janssen fit on synthetic profiles with known parameters, and EN 1991-4 against Janssen.
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

TEST(En1991_4, SameCurveAsJanssenAndKm) {
  EXPECT_NEAR(en1991_4_filling_pressure(9000, 5.0, 0.54, 0.38, 3.0), janssen_pressure(9000, 5.0, 0.54, 0.38, 3.0), 1e-9);
  // docs/theory.md §5 worked check: wheat, D2 steel, d_c = 5 m: z_o = 6.09 m, p_ho = 29.6 kPa.
  const double z_o = 5.0 / (4 * 0.54 * 0.38);
  EXPECT_NEAR(z_o, 6.09, 0.01);
  EXPECT_NEAR(9000 * 0.54 * z_o, 29.6e3, 0.1e3);
  EXPECT_NEAR(en1991_4_K(30.0 * M_PI / 180.0), 0.55, 1e-12);  // K_m = 1.1(1 − sin 30°)
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
