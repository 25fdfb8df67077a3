// The midpoint scheme as a case file runs it (integrator "runge_kutta_midpoint", "viscosity"): a
// free fall under viscosity follows the scheme's own closed form to round-off and the exact one to
// its error bound; a ball bouncing on a fixed ball closes the energy ledger with the viscosity's work
// booked; the loader refuses the scheme without viscosity and outside its window, naming the cause.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "../case_runs.hpp"
#include "silodem/case/case_error.hpp"
#include "silodem/case/case_loader.hpp"
#include "silodem/run/simulation.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

using silodem_test::refusal;

namespace {

constexpr double kR = 0.005, kDensity = 2500.0, kG = 9.81;

json falling_case(double mu, double dt, double duration, bool floor) {
  json balls = {{{"id", "ball"}, {"material", "grain"}, {"radius", kR}, {"position", {0, 0, 0.02}}}};
  if (floor) balls.push_back({{"id", "floor"}, {"material", "grain"}, {"radius", kR}, {"position", {0, 0, 0}}, {"fixed", true}});
  return {{"name", "midpoint"},
          {"gravity", {0, 0, -kG}},
          {"materials", {{"grain", {{"density", kDensity}, {"stiffness", 2e4}, {"damping", 0.0}}}}},
          {"balls", balls},
          {"integrator", {{"scheme", "runge_kutta_midpoint"}, {"viscosity", mu}}},
          {"time", {{"dt", dt}, {"duration", duration}}},
          {"output", {{"probes", {{{"type", "ball"}, {"name", "ball"}, {"balls", {"ball"}}}}}}}};
}

json run(const json& c, const std::string& name) {
  return silodem_test::run_in_scratch(c, "silodem_midpoint_" + name);
}


}  // namespace

TEST(MidpointCase, AFreeFallUnderViscosityFollowsTheSchemesClosedForm) {
  // v' = −g − μ v: each step multiplies v − v∞ by a = 1 − μΔt + (μΔt)²/2, v∞ = −g/μ; the exact
  // factor is e^{−μΔt}, so after n steps the two differ by about n (μΔt)³/6 · |v∞| e^{−μ t}.
  const double mu = 50.0, dt = 1e-3;
  const int n = 100;
  const json s = run(falling_case(mu, dt, n * dt, false), "fall");
  const double v = s["probes"]["ball"]["final_velocity"][2].get<double>();
  const double a = 1.0 - mu * dt + 0.5 * mu * dt * mu * dt, v_inf = -kG / mu;
  EXPECT_NEAR(v, v_inf * (1.0 - std::pow(a, n)), 1e-12 * std::abs(v_inf));
  const double exact = v_inf * (1.0 - std::exp(-mu * n * dt));
  EXPECT_NEAR(v, exact, n * std::pow(mu * dt, 3) / 6.0 * std::abs(v_inf) * std::exp(-mu * n * dt) * 1.1);
  EXPECT_GT(std::abs(v - exact), 0.0);  // the scheme is not exact: the oracle above is its own
}

TEST(MidpointCase, TheLedgerClosesWithTheViscositysWorkBooked) {
  // A ball dropped 10 mm onto a fixed ball, undamped contact, μ = 20 s⁻¹: by t = 0.1 s the
  // viscosity has taken two thirds of the 10 mm fall's energy; unbooked, the drift would be about that. The
  // scheme's own energy error is a gain of Ω⁴/4 per step in contact (|1 + z + z²/2|² on the
  // undamped pair): Ω = 0.028, 1.5·10⁻⁷ per step over two contacts of about 113 steps, 3.4·10⁻⁵ of
  // the energy; the trapezoid booking of the viscosity adds O((μΔt)²). Gate: 10⁻⁴ (measured 3.1·10⁻⁵).
  const json s = run(falling_case(20.0, 1e-5, 0.1, true), "bounce");
  const auto& e = s["energy"];
  const double m = kDensity * 4.0 / 3.0 * M_PI * kR * kR * kR;
  EXPECT_GT(e["dissipated"].get<double>(), 0.25 * m * kG * 0.01);
  EXPECT_LT(e["max_abs_relative_drift"].get<double>(), 1e-4);
}

TEST(MidpointCase, TheLoaderRefusesNoViscosityAndAViscosityOutsideTheWindow) {
  const std::string none = refusal(falling_case(0.0, 1e-5, 0.1, true));
  EXPECT_NE(none.find("viscosity"), std::string::npos) << none;
  // 2/Δt = 2·10⁵ s⁻¹: beyond it a free ball's velocity grows.
  const std::string high = refusal(falling_case(2.5e5, 1e-5, 0.1, true));
  EXPECT_NE(high.find("2/mu"), std::string::npos) << high;
  json vv = falling_case(20.0, 1e-5, 0.1, true);
  vv["integrator"]["scheme"] = "velocity_verlet";
  EXPECT_NE(refusal(vv).find("viscosity"), std::string::npos) << refusal(vv);
  json corrector = falling_case(20.0, 1e-5, 0.1, true);
  corrector["integrator"]["max_corrector_passes"] = 3;
  EXPECT_NE(refusal(corrector).find("corrector"), std::string::npos) << refusal(corrector);
}
