// Benchmark (issue 5 §3): the largest stable time step of every integrator on one linear
// spring–dashpot contact — the relative motion of two touching balls, ü = −ω²u − 2ζω u̇ — found
// by bisection on Ω = ωΔt, against the closed forms of docs/theory.md §7 (velocity Verlet 2, its
// damped variants, the predictor–corrector with m passes) and against the limit the case loader
// enforces (integrate/stability.hpp); then the tangential mode of a sticking history spring
// (bench/tangential_stability.cpp). Writes reports/stability.{json,md}.
//   build/bench/bench_stability [OUT_DIR]     (default: reports)
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "silodem/integrate/predictor_corrector.hpp"
#include "silodem/integrate/stability.hpp"
#include "silodem/integrate/velocity_verlet.hpp"
#include "tangential_stability.hpp"

using namespace silodem;

namespace {

/// Bounded after `steps` steps? (|u| stays below 10 × its start; m = k = 1, ω = 1).
bool stable(const std::function<std::unique_ptr<Integrator>()>& make, double zeta, double omega_dt, int steps) {
  Particles p;
  p.add({Vec3(1, 0, 0), Vec3::Zero(), 0.01, 1.0, 1.0, 0.0, 0, "b"}, false);
  const ForceEvaluation f = [zeta](Particles& q) {
    q.f[0] = Vec3(-q.x[0].x() - 2.0 * zeta * q.v[0].x(), 0.0, 0.0);
    return ForceTotals{};
  };
  auto in = make();
  in->reset(p, f);
  for (int n = 0; n < steps; ++n) {
    in->step(p, f, omega_dt);
    if (!(std::abs(p.x[0].x()) < 10.0)) return false;
  }
  return true;
}

/// Largest stable Ω in (0, 4] to 1e-4: bisection from the largest stable point of a 0.02 grid
/// (a scheme may have a stable island above a first unstable band; the grid finds the last one).
double limit(const std::function<std::unique_ptr<Integrator>()>& make, double zeta, int steps) {
  double lo = 0.0;
  for (int k = 1; k <= 200; ++k)
    if (stable(make, zeta, 0.02 * k, steps)) lo = 0.02 * k;
  double hi = lo + 0.02;
  while (hi - lo > 1e-4) {
    const double mid = 0.5 * (lo + hi);
    (stable(make, zeta, mid, steps) ? lo : hi) = mid;
  }
  return lo;
}

struct Scheme_ {
  std::string name;
  IntegratorSpec spec;
  std::function<std::unique_ptr<Integrator>()> make;
  std::function<double(double)> theory;  // closed form of docs/theory.md §7 (NAN: none given)
  std::string theory_rule;
};

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path out = argc > 1 ? argv[1] : "reports";
  const int steps = 4000;
  std::vector<Scheme_> schemes;
  {
    IntegratorSpec s;
    s.scheme = Scheme::VelocityVerlet;
    s.half_step_dashpot = true;
    schemes.push_back({"velocity_verlet_half_step", s, [] { return std::make_unique<VelocityVerlet>(Vec3::Zero(), true); },
                       [](double z) { return 2.0 * (std::sqrt(1 + z * z) - z); }, "2(sqrt(1+z^2) - z)"});
    s.half_step_dashpot = false;
    schemes.push_back({"velocity_verlet", s, [] { return std::make_unique<VelocityVerlet>(Vec3::Zero(), false); },
                       [](double z) { return 2.0 * (std::sqrt(1 + 4 * z * z) - 2 * z); }, "2(sqrt(1+4z^2) - 2z)"});
  }
  // PECE^m: docs/theory.md §7.4 gives the undamped limits 2.0 (m = 1), 2.185 (m = 3), 2.261 (m = 5),
  // even m weakly unstable for every Ω (so their "limit" depends on the run length).
  const std::vector<std::pair<int, double>> pc = {{1, 2.0}, {2, NAN}, {3, 2.185}, {5, 2.261}, {10, NAN}};
  for (const auto& [passes, undamped] : pc) {
    const int m = passes;  // a structured binding cannot be captured before C++20
    IntegratorSpec s;
    s.max_corrector_passes = m;
    const double u = undamped;
    schemes.push_back({"predictor_corrector_m" + std::to_string(m), s,
                       [m] { return std::make_unique<PredictorCorrector>(Vec3::Zero(), m, CorrectorStop::FixedPoint, 0.0); },
                       [u](double z) { return z == 0.0 ? u : NAN; }, "docs/theory.md §7.4 (undamped only)"});
  }
  nlohmann::json rows = nlohmann::json::array();
  std::printf("%-28s %5s %10s %10s %10s %9s\n", "scheme", "zeta", "measured", "theory", "loader", "dev");
  for (const auto& s : schemes)
    for (const double zeta : {0.0, 0.1, 0.3, 0.5, 0.9}) {
      const double m = limit(s.make, zeta, steps);
      const double th = s.theory(zeta);
      const double loader = stable_time_step(s.spec, 1.0, zeta).dt_max;
      const double dev = std::isfinite(th) ? m / th - 1.0 : NAN;
      std::printf("%-28s %5.2f %10.4f %10.4f %10.4f %+8.2f%%\n", s.name.c_str(), zeta, m, th, loader, 100 * dev);
      rows.push_back({{"scheme", s.name}, {"zeta", zeta}, {"measured_omega_dt", m},
                      {"theory_omega_dt", std::isfinite(th) ? nlohmann::json(th) : nlohmann::json(nullptr)},
                      {"theory_rule", s.theory_rule}, {"loader_omega_dt", loader}, {"steps", steps}});
    }
  const nlohmann::json tangential = tangential_rows(steps);
  std::filesystem::create_directories(out);
  std::ofstream(out / "stability.json") << std::setw(1)
                                        << nlohmann::json{{"what", "largest stable omega*dt on one linear contact"},
                                                          {"command", "build/bench/bench_stability reports"},
                                                          {"steps_per_trial", steps}, {"rows", rows},
                                                          {"tangential_rows", tangential}}
                                        << "\n";
  std::ofstream md(out / "stability.md");
  md << "# Stability limits on one linear contact\n\nWritten by `build/bench/bench_stability reports` "
        "(bench/stability_limits.cpp). Largest stable Ω = ωΔt (ω = √(k/m_eff) of the pair), found by bisection "
        "to 1e-4 with "
     << steps
     << " steps per trial (unstable: |u| exceeds 10 × its start), against the closed forms of docs/theory.md §7 and the "
        "limit the case loader enforces (integrate/stability.hpp). A dense packing is stiffer than one pair: its "
        "limit is lower (not measured here).\n\n| scheme | ζ | measured | theory | loader refuses above | measured/theory − 1 |\n|---|---|---|---|---|---|\n";
  for (const auto& r : rows) {
    const double measured = r["measured_omega_dt"].get<double>();
    char theory[32] = "—", dev[32] = "—", b[256];
    if (!r["theory_omega_dt"].is_null()) {
      const double th = r["theory_omega_dt"].get<double>();
      std::snprintf(theory, sizeof theory, "%.4f", th);
      std::snprintf(dev, sizeof dev, "%+.3f %%", 100.0 * (measured / th - 1.0));
    }
    std::snprintf(b, sizeof b, "| %s | %.1f | %.4f | %s | %.4f | %s |\n", r["scheme"].get<std::string>().c_str(),
                  r["zeta"].get<double>(), measured, theory, r["loader_omega_dt"].get<double>(), dev);
    md << b;
  }
  write_tangential_md(md, tangential, steps);
  return 0;
}
