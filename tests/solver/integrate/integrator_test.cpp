// Each integrator alone on free fall, an undamped and a damped oscillator; the multi-corrector
// against an independent Newmark (β = 1/6, γ = 1/2) solution; the predictor and corrector formulas.
#include <gtest/gtest.h>

#include <cmath>

#include "silodem/integrate/integrator.hpp"
#include "silodem/integrate/predictor_corrector.hpp"
#include "silodem/integrate/velocity_verlet.hpp"

using namespace silodem;

namespace {

Particles one_ball(const Vec3& x, const Vec3& v, double m = 2.0) {
  Particles p;
  p.add({x, v, 0.01, m, 1.0, 0.0, 0, "b"}, false);
  return p;
}

/// A linear spring–dashpot tying the ball to the origin along x: f = −k x − c v.
ForceEvaluation oscillator(double k, double c) {
  return [k, c](Particles& p) {
    p.f[0] = Vec3(-k * p.x[0].x() - c * p.v[0].x(), 0.0, 0.0);
    return ForceTotals{};
  };
}

std::vector<std::unique_ptr<Integrator>> all_schemes(const Vec3& g) {
  std::vector<std::unique_ptr<Integrator>> v;
  v.push_back(std::make_unique<PredictorCorrector>(g, 1, CorrectorStop::FixedPoint, 1e-12));
  v.push_back(std::make_unique<PredictorCorrector>(g, 20, CorrectorStop::FixedPoint, 1e-12));
  v.push_back(std::make_unique<VelocityVerlet>(g, false));
  v.push_back(std::make_unique<VelocityVerlet>(g, true));
  return v;
}

}  // namespace

TEST(Integrators, FreeFallIsExact) {
  const Vec3 g(0, 0, -9.81);
  for (auto& in : all_schemes(g)) {
    Particles p = one_ball(Vec3(0, 0, 1), Vec3(0.5, 0, 2));
    const ForceEvaluation none = [](Particles& q) { q.f[0].setZero(); return ForceTotals{}; };
    in->reset(p, none);
    const double dt = 1e-3;
    for (int n = 0; n < 1000; ++n) in->step(p, none, dt);
    EXPECT_NEAR(p.x[0].z(), 1 + 2 * 1.0 - 0.5 * 9.81, 1e-11);
    EXPECT_NEAR(p.x[0].x(), 0.5, 1e-12);
    EXPECT_NEAR(p.v[0].z(), 2 - 9.81, 1e-11);
  }
}

TEST(Integrators, UndampedOscillatorPeriodAndAmplitude) {
  // ω = 1 rad/s, Ω = 0.05: after one period every scheme returns to x = 1 to O(Ω²).
  for (auto& in : all_schemes(Vec3::Zero())) {
    Particles p = one_ball(Vec3(1, 0, 0), Vec3::Zero(), 1.0);
    const auto f = oscillator(1.0, 0.0);
    in->reset(p, f);
    const double dt = 0.05;
    const int n = int(std::round(2 * M_PI / dt));
    for (int i = 0; i < n; ++i) in->step(p, f, dt);
    const double t = n * dt;
    EXPECT_NEAR(p.x[0].x(), std::cos(t), 5e-3);
    EXPECT_NEAR(p.v[0].x(), -std::sin(t), 5e-3);
  }
}

TEST(Integrators, DampedOscillatorConvergesAtSecondOrder) {
  // x'' = −x − 2ζ x', ζ = 0.2, x(0) = 1, v(0) = 0; exact solution at t = 3.
  const double z = 0.2, w = std::sqrt(1 - z * z);
  const auto exact = [&](double t) { return std::exp(-z * t) * (std::cos(w * t) + z / w * std::sin(w * t)); };
  for (std::size_t s = 0; s < 4; ++s) {
    double err[2];
    for (int level = 0; level < 2; ++level) {
      auto in = std::move(all_schemes(Vec3::Zero())[s]);
      Particles p = one_ball(Vec3(1, 0, 0), Vec3::Zero(), 1.0);
      const auto f = oscillator(1.0, 2 * z);
      in->reset(p, f);
      const double dt = 0.01 / (1 << level);
      for (int i = 0; i < int(std::lround(3.0 / dt)); ++i) in->step(p, f, dt);
      err[level] = std::abs(p.x[0].x() - exact(3.0));
    }
    const double order = std::log2(err[0] / err[1]);
    if (s == 3) EXPECT_NEAR(order, 1.0, 0.3) << "half-step dashpot velocity is first order";
    else EXPECT_GT(order, 1.8) << "scheme " << s;
  }
}

TEST(PredictorCorrector, ConvergedCorrectorIsNewmarkLinearAcceleration) {
  // For x'' = −ω² x, Newmark β = 1/6, γ = 1/2 solved exactly per step (2x2 linear system):
  //   a1 = −ω² x1, x1 = x0 + h v0 + h²(a0/3 + a1/6), v1 = v0 + h(a0 + a1)/2.
  const double w2 = 4.0, h = 0.1;
  double x = 1.0, v = 0.3, a = -w2 * x;
  Particles p = one_ball(Vec3(x, 0, 0), Vec3(v, 0, 0), 1.0);
  const auto f = oscillator(w2, 0.0);
  PredictorCorrector pc(Vec3::Zero(), 200, CorrectorStop::FixedPoint, 1e-14);
  pc.reset(p, f);
  for (int n = 0; n < 50; ++n) {
    const double x1 = (x + h * v + h * h * a / 3.0) / (1.0 + w2 * h * h / 6.0);
    const double a1 = -w2 * x1;
    v += h * (a + a1) / 2.0;
    x = x1;
    a = a1;
    pc.step(p, f, h);
  }
  EXPECT_NEAR(p.x[0].x(), x, 1e-12);
  EXPECT_NEAR(p.v[0].x(), v, 1e-12);
}

TEST(PredictorCorrector, OneStepByHand) {
  // x0 = 1, v0 = 0, ω² = 1, h = 0.1. Predictor (18)(19): v_p = −0.1, x_p = 0.995.
  // Δü = −x_p − (−1) = 0.005; corrector (23): v = −0.1 + 0.05·0.005, x = 0.995 + 0.005·0.01/6.
  Particles p = one_ball(Vec3(1, 0, 0), Vec3::Zero(), 1.0);
  const auto f = oscillator(1.0, 0.0);
  PredictorCorrector pc(Vec3::Zero(), 1, CorrectorStop::FixedPoint, 1e-3);
  pc.reset(p, f);
  const StepReport r = pc.step(p, f, 0.1);
  EXPECT_NEAR(p.v[0].x(), -0.1 + 0.05 * 0.005, 1e-15);
  EXPECT_NEAR(p.x[0].x(), 0.995 + 0.005 * 0.01 / 6.0, 1e-15);
  EXPECT_EQ(r.corrector_passes, 1);
  EXPECT_EQ(r.force_evaluations, 2);  // at the predicted and at the corrected state
}

TEST(PredictorCorrector, StopTestsDiffer) {
  // A stiff oscillator: the fixed-point residual shrinks by ≈ Ω²/6 per pass and stops early;
  // the literal (26) compares |Δü| itself with ε and runs to the pass limit.
  const double w2 = 1e4, h = 0.01;  // Ω = 1
  Particles p1 = one_ball(Vec3(1, 0, 0), Vec3::Zero(), 1.0), p2 = p1;
  const auto f = oscillator(w2, 0.0);
  PredictorCorrector fixed(Vec3::Zero(), 30, CorrectorStop::FixedPoint, 1e-6);
  PredictorCorrector literal(Vec3::Zero(), 30, CorrectorStop::PaperLiteral, 1e-6);
  fixed.reset(p1, f);
  literal.reset(p2, f);
  const StepReport a = fixed.step(p1, f, h), b = literal.step(p2, f, h);
  EXPECT_LT(a.corrector_passes, 30);
  EXPECT_LT(a.corrector_residual, 1e-6);
  EXPECT_EQ(b.corrector_passes, 30);
  EXPECT_NEAR(p1.x[0].x(), p2.x[0].x(), 1e-9);  // both converged to the same state
}
