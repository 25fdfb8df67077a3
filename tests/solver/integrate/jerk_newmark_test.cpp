// Seed 003's iterative "jerk" refinement (the thesis's (26)–(31), written out here from the thesis,
// as an independent oracle) is the paper's multiple corrector: with the same stop test (corrector_stop
// "relative", the thesis's (31)) silodem's PredictorCorrector takes the same steps to round-off on a
// Hertz impact. Converged, both are Newmark's linear-acceleration scheme: second order in the
// contact time against the Hertz closed form. The passes grow as ωΔt → √6 as (Ω²/6)^j predicts and
// do not converge beyond it, which the step reports (docs/theory.md §7.4).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <vector>

#include "silodem/case/case_loader.hpp"
#include "silodem/integrate/predictor_corrector.hpp"
#include "silodem/run/simulation.hpp"

using namespace silodem;

namespace {

// A ball of mass m meeting a fixed wall at x = 0 along −x, Hertz force K δ^{3/2}, δ = r − x.
constexpr double kMass = 0.0327, kRadius = 0.01, kK = 1e8, kV0 = 1.0;

double hertz_acceleration(double x) {
  const double overlap = kRadius - x;
  return overlap > 0.0 ? kK * std::pow(overlap, 1.5) / kMass : 0.0;
}

struct State {
  double x, v;
};

/// One step of the thesis's jerk iteration: b = 0 on the first iteration, then b = (a_{t+Δt} − a_t)/Δt
/// (29), positions by (28), until |(a^k − a^{k−1})/a^k| < ε_a (31), the first a^{k−1} being a_t; the
/// accepted state by (27)–(28) with the last b, and the next step's a_t evaluated there.
State jerk_step(State s, double& a_t, double h, double eps_a, int& iterations) {
  double b = 0.0, a_prev = a_t;
  for (iterations = 1; iterations <= 1000; ++iterations) {
    const double x = s.x + s.v * h + a_t * h * h / 2.0 + b * h * h * h / 6.0;  // (28)
    const double a = hertz_acceleration(x);
    b = (a - a_t) / h;  // (29)
    const bool done = a != 0.0 ? std::abs((a - a_prev) / a) < eps_a : a == a_prev;  // (31)
    a_prev = a;
    if (done) break;
  }
  const State next{s.x + s.v * h + a_t * h * h / 2.0 + b * h * h * h / 6.0, s.v + a_t * h + b * h * h / 2.0};
  a_t = hertz_acceleration(next.x);
  return next;
}

Particles one_ball(const State& s) {
  Particles p;
  p.add({Vec3(s.x, 0, 0), Vec3(s.v, 0, 0), kRadius, kMass, 1.0, 0.0, 0, "ball"}, false);
  return p;
}

const ForceEvaluation kHertzWall = [](Particles& q) {
  q.f[0] = Vec3(kMass * hertz_acceleration(q.x[0].x()), 0, 0);
  return ForceTotals{};
};

/// The Hertz contact time of this impact: t_c = 2 (δ_max/v0) ∫₀¹ du/√(1 − u^{5/2}), δ_max from
/// ½ m v0² = (2/5) K δ_max^{5/2}; the integral by Gauss–Legendre after u = 1 − s² (smooth in s).
double hertz_contact_time() {
  const double delta_max = std::pow(5.0 * kMass * kV0 * kV0 / (4.0 * kK), 0.4);
  double integral = 0.0;
  const int panels = 2000;
  const double nodes[2] = {-1.0 / std::sqrt(3.0), 1.0 / std::sqrt(3.0)};
  for (int k = 0; k < panels; ++k)
    for (const double node : nodes) {
      const double s = (k + 0.5 + 0.5 * node) / panels, u = 1.0 - s * s;
      integral += 0.5 / panels * 2.0 * s / std::sqrt(1.0 - std::pow(u, 2.5));
    }
  return 2.0 * delta_max / kV0 * integral;
}

/// The contact time a run sees: from the first step in contact to the first after it, each end at
/// the linear interpolation of the gap's zero between the steps (an O(h²) estimate).
double measured_contact_time(Integrator& in, double h) {
  Particles p = one_ball({kRadius + 0.5 * kV0 * h, -kV0});
  in.reset(p, kHertzWall);
  double t = 0.0, start = NAN, gap_prev = p.x[0].x() - kRadius;
  for (int n = 0; n < 100000; ++n) {
    in.step(p, kHertzWall, h);
    t += h;
    const double gap = p.x[0].x() - kRadius;
    const double crossing = t - h * gap / (gap - gap_prev);
    if (std::isnan(start) && gap < 0.0) start = crossing;
    if (!std::isnan(start) && gap > 0.0) return crossing - start;
    gap_prev = gap;
  }
  return NAN;
}

}  // namespace

TEST(JerkNewmark, TheThesisJerkIterationAndTheRelativeStopCorrectorTakeTheSameSteps) {
  const double t_c = hertz_contact_time(), h = t_c / 30.0, eps_a = 1e-5;
  State s{kRadius + 0.3 * kV0 * h, -kV0};
  double a_t = hertz_acceleration(s.x);
  Particles p = one_ball(s);
  PredictorCorrector pc(Vec3::Zero(), 1000, CorrectorStop::Relative, eps_a);
  pc.reset(p, kHertzWall);
  double worst = 0.0;
  int passes_total = 0, iterations_total = 0;
  for (int n = 0; n < 60; ++n) {
    int iterations = 0;
    s = jerk_step(s, a_t, h, eps_a, iterations);
    const StepReport rep = pc.step(p, kHertzWall, h);
    iterations_total += iterations, passes_total += rep.corrector_passes;
    worst = std::max({worst, std::abs(p.x[0].x() - s.x) / kRadius, std::abs(p.v[0].x() - s.v) / kV0});
  }
  EXPECT_LT(worst, 1e-13);  // the same arithmetic in another order (measured: bit for bit equal)
  EXPECT_EQ(passes_total, iterations_total);
  EXPECT_GT(s.v, 0.9 * kV0);  // the ball has come back
}

TEST(JerkNewmark, ConvergedTheCorrectorIsSecondOrderInTheHertzContactTime) {
  // Newmark (β = 1/6, γ = 1/2): second order; the elastic Hertz force is C¹ at the touch, so the onset
  // costs no order. Observed order from t_c/20 → t_c/40 → t_c/80 must lie in [1.8, 2.2].
  const double t_c = hertz_contact_time();
  std::vector<double> errors;
  for (const double divisor : {20.0, 40.0, 80.0}) {
    PredictorCorrector pc(Vec3::Zero(), 1000, CorrectorStop::FixedPoint, 1e-9 * kK * std::pow(1e-4, 1.5) / kMass);
    errors.push_back(std::abs(measured_contact_time(pc, t_c / divisor) / t_c - 1.0));
  }
  for (std::size_t k = 1; k < errors.size(); ++k) {
    const double order = std::log2(errors[k - 1] / errors[k]);
    EXPECT_GE(order, 1.8) << "errors " << errors[k - 1] << " -> " << errors[k];
    EXPECT_LE(order, 2.2) << "errors " << errors[k - 1] << " -> " << errors[k];
  }
  EXPECT_LT(errors.back(), 1e-3);
}

TEST(JerkNewmark, PassesGrowAsOmegaNearsRootSixAndDoNotConvergeBeyond) {
  // A linear spring ω = 1 from x = 1 at rest: each pass multiplies the velocity's error by −Ω²/6, so
  // reaching ε from the first residual r0 takes about log(ε/r0)/log(Ω²/6) passes.
  const ForceEvaluation spring = [](Particles& q) {
    q.f[0] = Vec3(-q.x[0].x(), 0, 0);
    return ForceTotals{};
  };
  const double eps = 1e-10;
  for (const double Omega : {1.0, 2.0, 2.3, 2.4}) {
    Particles p = one_ball({1.0, 0.0});
    p.m[0] = 1.0;
    PredictorCorrector pc(Vec3::Zero(), 1000, CorrectorStop::FixedPoint, eps);
    pc.reset(p, spring);
    const StepReport rep = pc.step(p, spring, Omega);
    const double r0 = Omega * Omega / 2.0;  // |Δü⁽⁰⁾|: the predictor's x falls by Ω²/2
    const double predicted = std::log(eps / r0) / std::log(Omega * Omega / 6.0);
    EXPECT_NEAR(rep.corrector_passes, predicted, 0.05 * predicted + 2.0) << "Omega " << Omega;
    EXPECT_LT(rep.corrector_residual, eps);
  }
  Particles p = one_ball({1.0, 0.0});
  p.m[0] = 1.0;
  PredictorCorrector pc(Vec3::Zero(), 1000, CorrectorStop::FixedPoint, eps);
  ASSERT_TRUE(pc.corrector_tolerance().has_value());
  pc.reset(p, spring);
  const StepReport rep = pc.step(p, spring, 2.5);
  EXPECT_EQ(rep.corrector_passes, 1000);
  EXPECT_GE(rep.corrector_residual, *pc.corrector_tolerance());
}

// A run says when its corrector ran out of passes: the loader admits Δt by one pair's limit, so a
// stiffer mode, a Hertz contact pressed harder than the check assumed, or a tolerance too tight for
// the pass limit can leave steps unconverged. Here: three passes against a tolerance of 10⁻¹² g.
TEST(JerkNewmark, ARunReportsACorrectorThatRanOutOfPasses) {
  const auto run = [](int passes, double p_acc) {
    nlohmann::json c = {
        {"name", "corrector_report"},
        {"materials", {{"grain", {{"density", 2500.0}, {"stiffness", 2e4}, {"damping", 0.0}}}}},
        {"balls",
         {{{"id", "ball"}, {"material", "grain"}, {"radius", 0.005}, {"position", {0, 0, 0.0101}}},
          {{"id", "floor"}, {"material", "grain"}, {"radius", 0.005}, {"position", {0, 0, 0}}, {"fixed", true}}}},
        {"integrator", {{"scheme", "predictor_corrector"}, {"max_corrector_passes", passes}, {"p_acc", p_acc}}},
        {"time", {{"dt_per_contact_time", 0.02}, {"duration", 0.05}}}};
    const std::filesystem::path out = std::filesystem::temp_directory_path() / "silodem_corrector_report";
    std::filesystem::remove_all(out);  // the test's own scratch
    return silodem::run_case(silodem::load_case(c), {out, false, false});
  };
  const nlohmann::json tight = run(3, 1e-12);
  EXPECT_FALSE(tight["run"]["corrector_converged"].get<bool>());
  EXPECT_GE(tight["run"]["corrector_residual_max"].get<double>(), tight["run"]["corrector_tolerance"].get<double>());
  const nlohmann::json loose = run(50, 1e-3);
  EXPECT_TRUE(loose["run"]["corrector_converged"].get<bool>());
  EXPECT_GT(loose["run"]["corrector_passes_max"].get<int>(), 1);
}
