// The tangential mode of bench_stability (issue 27 §2): a ball held on a floor ball by a sticking
// linear history spring, stepped through the real frictional force loop and integrators (the set-up
// of tests/solver/integrate/floor_contact.hpp), its largest stable Ω_t = ω_t Δt found by bisection
// against the closed forms of docs/theory.md §7.7 and the loader's rules.
#include "tangential_stability.hpp"

#include <cmath>
#include <complex>
#include <cstdio>
#include <functional>

#include "../tests/solver/integrate/floor_contact.hpp"
#include "silodem/integrate/stability.hpp"

using namespace silodem;
using silodem::floor_test::FloorContact;
using silodem::floor_test::FloorSpec;

namespace {

FloorSpec spec_for(double zeta_t) { return floor_test::sticking_spec(zeta_t); }

/// Bounded after `steps` steps? The slip amplitude (√ of its energy ratio) over the last quarter of
/// the run stays below 10 × its largest value over the first quarter, and the ball within half its
/// overlap of its resting height. Against the first quarter, not the start: near a limit the energy
/// measure swings by a bounded factor (1/(1 − Ω²/4) for velocity Verlet near Ω = 2, a transient of
/// about 10 in the first steps of two passes), which is not growth.
bool stable(const FloorSpec& s, const IntegratorSpec& scheme, double dt, int steps) {
  FloorContact c(s, dt);
  c.start_slip_mode(1e-3);
  auto in = floor_test::make_scheme(scheme, Vec3(0, 0, -s.g));
  const double e0 = c.slip_energy(in->reset(c.p, c.eval));
  double first = 0.0;
  for (int n = 0; n < steps; ++n) {
    const StepReport r = c.step(*in, dt);
    const double a = std::sqrt(c.slip_energy(r.totals) / e0);
    if (!std::isfinite(a) || !(std::abs(c.lift()) < 0.5 * c.static_overlap())) return false;
    if (n < steps / 4) first = std::max(first, a);
    else if (n >= steps - steps / 4 && a > 10.0 * first) return false;
  }
  return true;
}

/// Largest stable Ω in (0, 3] to 1e-4, bisected from the largest stable point of a 0.05 grid.
double limit(const std::function<bool(double)>& ok) {
  double lo = 0.0;
  for (int k = 1; k <= 60; ++k)
    if (ok(0.05 * k)) lo = 0.05 * k;
  double hi = lo + 0.05;
  while (hi - lo > 1e-4) {
    const double mid = 0.5 * (lo + hi);
    (ok(mid) ? lo : hi) = mid;
  }
  return lo;
}

/// docs/theory.md §7.7: the m-pass predictor–corrector on (ξ, v) has the step matrix
/// [[1 − Ω²A, ΩB], [−ΩA, B]] (ω_t = 1), A = (1 + qg)/(1 + g), B = ((1 − q)(1 − Ωζ) + q(1 − 2Ωζ)(1 + g))/(1 + g),
/// g = Ω²/2 + ζΩ, q = (−g)^m; its spectral radius, from trace 1 − Ω²A + B and determinant B.
double pc_radius(double w, double zeta, int m) {
  const double g = 0.5 * w * w + zeta * w, q = std::pow(-g, m);
  const double a = (1.0 + q * g) / (1.0 + g), b = ((1.0 - q) * (1.0 - w * zeta) + q * (1.0 - 2.0 * w * zeta) * (1.0 + g)) / (1.0 + g);
  const double tr = 1.0 - w * w * a + b;
  const std::complex<double> d = std::sqrt(std::complex<double>(tr * tr - 4.0 * b));
  return std::max(std::abs(0.5 * (tr + d)), std::abs(0.5 * (tr - d)));
}

double pc_theory(double zeta, int m) {
  double lo = 0.0;  // the same grid search, on the closed form, to 1e-10
  for (int k = 1; k <= 600; ++k)
    if (pc_radius(0.005 * k, zeta, m) <= 1.0 + 1e-12) lo = 0.005 * k;
  double hi = lo + 0.005;
  while (hi - lo > 1e-10) {
    const double mid = 0.5 * (lo + hi);
    (pc_radius(mid, zeta, m) <= 1.0 + 1e-12 ? lo : hi) = mid;
  }
  return lo;
}

struct Row_ {
  std::string name;
  IntegratorSpec spec;
  std::function<double(double)> theory;
  std::string rule;
};

}  // namespace

nlohmann::json tangential_rows(int steps) {
  std::vector<Row_> schemes;
  IntegratorSpec s;
  s.scheme = Scheme::VelocityVerlet;
  s.half_step_dashpot = true;
  schemes.push_back({"velocity_verlet_half_step", s, [](double z) { return 2.0 * (std::sqrt(1 + z * z) - z); },
                     "2(sqrt(1+z^2) - z), the normal mode's"});
  s.half_step_dashpot = false;
  schemes.push_back({"velocity_verlet", s, [](double z) { return std::sqrt(2 + 4 * z * z) - 2 * z; }, "sqrt(2+4z^2) - 2z"});
  for (const int m : {1, 2, 3, 5, 10}) {
    IntegratorSpec pc;
    pc.max_corrector_passes = m;
    schemes.push_back({"predictor_corrector_m" + std::to_string(m), pc, [m](double z) { return pc_theory(z, m); },
                       m % 2 ? "sqrt(2+z^2) - z" : "spectral radius of the closed-form step matrix"});
  }
  nlohmann::json rows = nlohmann::json::array();
  std::printf("\ntangential mode\n%-28s %5s %10s %10s %10s %10s %9s\n", "scheme", "zeta", "measured", "theory", "loader",
              "tangential", "dev");
  for (const auto& sc : schemes)
    for (const double zeta : {0.0, 0.1, 0.3, 0.5, 0.9}) {
      const FloorSpec f = spec_for(zeta);
      FloorContact probe(f, 1e-6);
      const double w_t = std::sqrt(f.shear_ratio * f.k_n / probe.slip_mass());
      const double measured = limit([&](double big) { return stable(f, sc.spec, big / w_t, steps); });
      const double th = sc.theory(zeta);
      // What case/feasibility.cpp refuses today (the normal rule at ω_t), and the tangential rule.
      const double loader = stable_time_step(sc.spec, 1.0, zeta).dt_max;
      const double tangential = stable_tangential_time_step(sc.spec, 1.0, zeta).dt_max;
      std::printf("%-28s %5.2f %10.4f %10.4f %10.4f %10.4f %+8.3f%%\n", sc.name.c_str(), zeta, measured, th, loader,
                  tangential, 100.0 * (measured / th - 1.0));
      rows.push_back({{"scheme", sc.name}, {"zeta_t", zeta}, {"measured_omega_t_dt", measured}, {"theory_omega_t_dt", th},
                      {"theory_rule", sc.rule}, {"loader_omega_t_dt", loader}, {"tangential_rule_omega_t_dt", tangential},
                      {"steps", steps}});
    }
  return rows;
}

void write_tangential_md(std::ostream& md, const nlohmann::json& rows, int steps) {
  md << "\n## The tangential mode of a sticking contact\n\nA ball held on a floor ball by a linear history spring "
        "(μ = 10⁶: it never slides), started in its slip mode, through the real frictional force loop "
        "(tests/solver/integrate/floor_contact.hpp). Largest stable Ω_t = ω_t Δt, ω_t = √(k_t/m_t), 1/m_t = 1/m + "
        "a²/I (m_t = 2/7 m for a = r; for two equal balls m_t = 2/7 m* = m/7), ζ_t = γ_t/(2√(k_t m_t)); bisection "
        "to 1e-4 with "
     << steps
     << " steps per trial (unstable: the slip amplitude over the last quarter exceeds 10 × its largest value over the "
        "first quarter, which bounded swings of the energy measure near a limit do not; docs/theory.md §7.7). k_t = 2 k_n keeps the normal "
        "mode at Ω_t/2.65, stable throughout. Theory: docs/theory.md §7.7 (closed forms for velocity Verlet and odd "
        "pass counts; the spectral radius of the closed-form step matrix for even ones). \"loader today\" is what "
        "case/feasibility.cpp applies to this mode (the normal-mode rule at ω_t); \"tangential rule\" is "
        "stable_tangential_time_step (integrate/stability.hpp).\n\n| scheme | ζ_t | measured | theory | loader today "
        "refuses above | tangential rule refuses above | measured/theory − 1 |\n|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows) {
    const double measured = r["measured_omega_t_dt"].get<double>(), th = r["theory_omega_t_dt"].get<double>();
    char b[320];
    std::snprintf(b, sizeof b, "| %s | %.1f | %.4f | %.4f | %.4f | %.4f | %+.3f %% |\n", r["scheme"].get<std::string>().c_str(),
                  r["zeta_t"].get<double>(), measured, th, r["loader_omega_t_dt"].get<double>(),
                  r["tangential_rule_omega_t_dt"].get<double>(), 100.0 * (measured / th - 1.0));
    md << b;
  }
}
