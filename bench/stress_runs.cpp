// Benchmark (issue 5 §3): runs that stress the integration — energy drift over 10⁷ steps of an
// undamped packing, impacts fast enough to overlap 10 % of the radius, wall/grain stiffness
// ratios of 10⁴ and 10⁻⁴ — each against its oracle, and too-fast impacts that the guards must
// stop cleanly. Writes reports/stress_runs.{json,md}.
//   build/bench/bench_stress_runs [OUT_DIR] [DRIFT_STEPS]   (defaults: reports, 10000000)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "silodem/case/case_loader.hpp"
#include "silodem/run/simulation.hpp"

namespace fs = std::filesystem;
using nlohmann::json;
using namespace silodem;

namespace {

const fs::path kWork = fs::temp_directory_path() / "silodem_bench_stress";
constexpr double kR = 0.005, kRho = 2500.0, kK = 2e4;  // per ball; equal pair in series (11): k/2
const double kMass = kRho * 4.0 / 3.0 * M_PI * kR * kR * kR;
const double kOmegaPair = std::sqrt((kK / 2.0) / (kMass / 2.0));

struct Outcome {
  json summary;            // empty if a guard stopped the run
  std::string error;       // the RunError's first line
  bool non_finite = false; // NaN or inf in any result file (complete or .failed)
  std::vector<std::vector<double>> series;
  std::vector<std::string> columns;
  double column_max(const std::string& c) const {
    const size_t k = size_t(std::find(columns.begin(), columns.end(), c) - columns.begin());
    double m = -INFINITY;
    for (const auto& r : series) m = std::max(m, r.at(k));
    return m;
  }
  double last(const std::string& c) const {
    return series.back().at(size_t(std::find(columns.begin(), columns.end(), c) - columns.begin()));
  }
};

bool has_non_finite(const fs::path& f) {
  std::ifstream in(f);
  const std::string s((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const char* bad : {"nan", "NaN", "inf", "Inf"})
    if (s.find(bad) != std::string::npos) return true;
  return false;
}

Outcome run(const json& c, const std::string& name) {
  Outcome o;
  const fs::path out = kWork / name, failed = out.string() + ".failed";
  fs::remove_all(out);
  fs::remove_all(failed);
  fs::path dir = out;
  try {
    o.summary = run_case(load_case(c), {out, false, false});
  } catch (const RunError& e) {
    o.error = std::string(e.what()).substr(0, std::string(e.what()).find(" [last state"));
    dir = failed;
  }
  for (const auto& f : fs::directory_iterator(dir))
    if (f.is_regular_file()) o.non_finite |= has_non_finite(f.path());
  std::ifstream s(dir / "series.csv");
  std::string line, cell;
  std::getline(s, line);
  for (std::stringstream h(line); std::getline(h, cell, ',');) o.columns.push_back(cell);
  while (std::getline(s, line)) {
    std::vector<double> row;
    for (std::stringstream r(line); std::getline(r, cell, ',');) row.push_back(std::stod(cell));
    o.series.push_back(row);
  }
  return o;
}

json material(double k, double zeta, double m_eff = kMass / 2.0) {
  // c per ball from the pair's ζ (one material in series (11): k_pair = k/2, c_pair = c/2).
  return {{"density", kRho}, {"stiffness", k}, {"damping", 2.0 * zeta * 2.0 * std::sqrt(k / 2.0 * m_eff)}};
}

json base_case(const std::string& name, const json& balls, double dt, double duration, const json& integrator) {
  return {{"format", "silodem-case/1"}, {"name", name}, {"seed", 1}, {"gravity", {0.0, 0.0, 0.0}},
          {"materials", {{"grain", material(kK, 0.0)}}}, {"balls", balls}, {"integrator", integrator},
          {"time", {{"dt", dt}, {"duration", duration}}}};
}

/// A caged FCC block of touching balls with random velocities: contacts open and close all the time.
json gas_block(int cells, double speed) {
  json balls = json::array();
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double h = kR * std::sqrt(2.0);  // nearest neighbours at h√2 = 2r: touching
  auto inside = [cells](int i, int j, int k) { return i >= 0 && j >= 0 && k >= 0 && i <= cells && j <= cells && k <= cells; };
  for (int i = -1; i <= cells + 1; ++i)
    for (int j = -1; j <= cells + 1; ++j)
      for (int k = -1; k <= cells + 1; ++k) {
        if ((i + j + k) % 2 != 0) continue;
        const std::string id = std::to_string(balls.size());
        if (inside(i, j, k))
          balls.push_back({{"id", "m" + id}, {"material", "grain"}, {"radius", kR * 0.97}, {"position", {i * h, j * h, k * h}},
                           {"velocity", {speed * u(rng), speed * u(rng), speed * u(rng)}}});
        else
          balls.push_back({{"id", "w" + id}, {"material", "grain"}, {"radius", kR * 0.97}, {"position", {i * h, j * h, k * h}},
                           {"fixed", true}});
      }
  return balls;
}

}  // namespace

int main(int argc, char** argv) {
  const fs::path out = argc > 1 ? argv[1] : "reports";
  const long drift_steps = argc > 2 ? std::stol(argv[2]) : 10000000L;
  const double tc = M_PI / kOmegaPair, dt = tc / 50.0;  // undamped contact time of the stiffest pair
  const std::string command = "build/bench/bench_stress_runs " + out.string() + " " + std::to_string(drift_steps);
  json report = {{"command", command}, {"dt_over_contact_time", 0.02}};
  std::vector<std::string> md;
  char b[1024];

  // 1. Energy drift of an undamped packing over drift_steps steps.
  md.push_back("## Energy drift of an undamped packing\n\nA caged FCC block (63 mobile balls, r = 4.85 mm, "
               "12 neighbours each, 3 % gaps) with random velocities up to 0.05 m/s (overlaps up to about 1 % of r), "
               "no gravity, no damping: contacts open and close all the time. Δt = t_c/50. |E − E₀|/E₀ from the "
               "energy ledger (kinetic + elastic, nothing dissipated), sampled every 10⁵ steps. A symplectic scheme "
               "(Verlet) keeps a bounded error on smooth forces; the force's kink at touch lets it walk.\n\n"
               "| scheme | steps | wall s | max \\|drift\\| to 10⁵ | to 10⁶ | to 10⁷ | final drift |\n|---|---|---|---|---|---|---|");
  json drift = json::array();
  for (const auto& [name, integ] : std::vector<std::pair<std::string, json>>{
           {"velocity_verlet", {{"scheme", "velocity_verlet"}}},
           {"predictor_corrector_m1", {{"scheme", "predictor_corrector"}, {"max_corrector_passes", 1}}},
           {"predictor_corrector_m3", {{"scheme", "predictor_corrector"}, {"max_corrector_passes", 3}}}}) {
    json c = base_case("drift_" + name, gas_block(4, 0.05), dt, dt * double(drift_steps) * (1 + 1e-12), integ);
    c["output"] = {{"series_interval", dt * 1e5}};
    const Outcome o = run(c, "drift_" + name);
    const size_t k = size_t(std::find(o.columns.begin(), o.columns.end(), "rel_drift") - o.columns.begin());
    double upto[3] = {0, 0, 0};
    for (size_t i = 0; i < o.series.size(); ++i)
      for (int d = 0; d < 3; ++d)
        if (double(i) * 1e5 <= std::pow(10.0, 5 + d) + 0.5) upto[d] = std::max(upto[d], std::abs(o.series[i][k]));
    const double wall = o.summary.empty() ? NAN : o.summary["run"]["wall_seconds"].get<double>();
    std::snprintf(b, sizeof b, "| %s | %ld | %.0f | %.2e | %.2e | %.2e | %+.2e |%s", name.c_str(), drift_steps, wall, upto[0],
                  upto[1], upto[2], o.series.empty() ? NAN : o.series.back()[k], o.error.empty() ? "" : (" stopped: " + o.error).c_str());
    md.push_back(b);
    std::printf("%s\n", b);
    drift.push_back({{"scheme", name}, {"steps", drift_steps}, {"wall_seconds", wall}, {"max_abs_drift_1e5", upto[0]},
                     {"max_abs_drift_1e6", upto[1]}, {"max_abs_drift_1e7", upto[2]}, {"error", o.error}});
  }
  report["drift"] = drift;

  // 2. Head-on impacts: δ_max = (v/ω) exp(−ζ φ/s), s = √(1 − ζ²), φ = arctan(s/ζ) (φ = π/2 at ζ = 0), for
  // the linear spring–dashpot; a speed chosen for δ_max = 0.1 r must reach it, and one for 1.0 r must
  // be stopped by the overlap guard (default 0.5 r) without a non-finite number in any file.
  md.push_back("\n## High-speed impacts\n\nTwo equal balls head on, or a ball on a fixed wall ball (k_pair and m_eff "
               "of that pair), unclamped linear spring–dashpot, velocity Verlet, Δt = t_c/50 of the pair, overlap "
               "sampled every step. Closed form δ_max = (v/ω) exp(−ζφ/s), s = √(1−ζ²), φ = arctan(s/ζ); "
               "e = exp(−ζπ/s). The speed is set for δ_max = 0.1 r (rows 'target 0.1') or 1.0 r (the overlap "
               "guard, 0.5 r by default, must stop the run cleanly).\n\n"
               "| pair | ζ | target δ/r | speed m/s | δ_max/r measured | closed form | e measured | closed form | outcome |\n|---|---|---|---|---|---|---|---|---|");
  json impacts = json::array();
  for (const bool wall : {false, true})
    for (const double zeta : {0.0, 0.3})
      for (const double target : {0.1, 1.0}) {
        const double m_eff = wall ? kMass : kMass / 2.0, k_pair = kK / 2.0;
        const double w = std::sqrt(k_pair / m_eff), s = std::sqrt(1.0 - zeta * zeta);
        const double phi = zeta == 0.0 ? M_PI / 2.0 : std::atan(s / zeta);
        const double reach = target * kR / std::exp(-zeta * phi / s);
        const double v_rel = reach * w;
        json balls = json::array();
        if (wall) {
          balls.push_back({{"id", "a"}, {"material", "grain"}, {"radius", kR}, {"position", {-kR * 1.001, 0.0, 0.0}}, {"velocity", {v_rel, 0.0, 0.0}}});
          balls.push_back({{"id", "w"}, {"material", "grain"}, {"radius", kR}, {"position", {kR * 1.001, 0.0, 0.0}}, {"fixed", true}});
        } else {
          balls.push_back({{"id", "a"}, {"material", "grain"}, {"radius", kR}, {"position", {-kR * 1.001, 0.0, 0.0}}, {"velocity", {v_rel / 2, 0.0, 0.0}}});
          balls.push_back({{"id", "b"}, {"material", "grain"}, {"radius", kR}, {"position", {kR * 1.001, 0.0, 0.0}}, {"velocity", {-v_rel / 2, 0.0, 0.0}}});
        }
        const double tc_pair = M_PI / (w * s), step = tc_pair / 50.0;
        json c = base_case("impact", balls, step, 2.0 * tc_pair + 0.002 * kR / v_rel, {{"scheme", "velocity_verlet"}});
        c["materials"]["grain"] = material(kK, zeta, m_eff);
        c["output"] = {{"series_interval", step}};
        const Outcome o = run(c, "impact");
        const double measured = o.column_max("max_overlap_ratio");
        // e from the kinetic energy after separation (ball–ball: equal and opposite speeds).
        const double e = o.error.empty() ? std::sqrt(o.last("E_kin") / o.series.front().at(1)) : NAN;
        const double e_th = std::exp(-zeta * M_PI / s);
        const std::string outcome = o.error.empty() ? "completed" : "stopped: " + o.error.substr(0, o.error.find(';'));
        std::snprintf(b, sizeof b, "| %s | %.1f | %.1f | %.2f | %.4f | %.4f | %.4f | %.4f | %s%s |", wall ? "ball–wall" : "ball–ball",
                      zeta, target, v_rel, measured, o.error.empty() ? target : NAN, e, e_th, outcome.c_str(),
                      o.non_finite ? " — NON-FINITE VALUE IN RESULTS" : "");
        md.push_back(b);
        std::printf("%s\n", b);
        impacts.push_back({{"wall", wall}, {"zeta", zeta}, {"target_overlap_ratio", target}, {"speed", v_rel},
                           {"measured_overlap_ratio", measured}, {"e", o.error.empty() ? json(e) : json(nullptr)}, {"e_closed_form", e_th},
                           {"error", o.error}, {"non_finite_in_results", o.non_finite}});
      }
  report["impacts"] = impacts;

  // 3. Wall/grain stiffness ratios of 10⁴ and 10⁻⁴: 216 grains fall onto a floor of wall balls and
  // settle (restitution 0.3); at rest the floor carries their weight.
  md.push_back("\n## Wall/grain stiffness ratio\n\n216 grains (r 4-5 mm, k = 2e4 N/m, or 4e6 N/m with the soft wall, restitution 0.3) dropped from a lattice "
               "into a box of fixed wall balls (r 5 mm, 10 mm grid) whose own k is 10⁴ or 10⁻⁴ times the grains', "
               "Δt = t_c/25 of the stiffest pair (`dt_per_contact_time` 0.04) (pairs in series (11), so a stiff wall meets a grain at about the "
               "grain's k and a soft wall sets a soft pair), velocity Verlet, 1 s. Oracle: at rest the vertical "
               "wall force equals the weight.\n\n| k_wall / k_grain | steps | wall s | wall load / weight − 1 | E_kin at end (J) | "
               "max overlap / r | ledger drift | outcome |\n|---|---|---|---|---|---|---|---|");
  json ratios = json::array();
  for (const double ratio : {1.0, 1e4, 1e-4}) {
    // A wall 10⁴ times softer than k = 2e4 would let the grains sink through it (weight/k_pair > r):
    // that scene takes stiffer grains, so the soft wall still carries the column with small overlaps.
    const double k_grain = ratio < 1.0 ? 4e6 : kK;
    json balls = json::array();
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> radius(0.004, 0.005);
    double weight = 0.0;
    const int m = 9;  // wall grid 9 x 9, 10 mm pitch
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j)
        for (int k = 0; k < 12; ++k) {
          const bool floor = k == 0, side = i == 0 || j == 0 || i == m - 1 || j == m - 1;
          if (!(floor || side)) continue;
          balls.push_back({{"id", "w" + std::to_string(balls.size())}, {"material", "wall"}, {"radius", 0.005},
                           {"position", {i * 0.01, j * 0.01, k * 0.01}}, {"fixed", true}});
        }
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        for (int k = 0; k < 6; ++k) {
          const double r = radius(rng);
          weight += kRho * 4.0 / 3.0 * M_PI * r * r * r * 9.81;
          balls.push_back({{"id", "g" + std::to_string(balls.size())}, {"material", "grain"}, {"radius", r},
                           {"position", {0.015 + i * 0.01, 0.015 + j * 0.01, 0.015 + k * 0.011}}});
        }
    json c = base_case("stiffness_ratio", balls, 1.0, 1.5, {{"scheme", "velocity_verlet"}});
    c["gravity"] = {0.0, 0.0, -9.81};
    c["materials"] = {{"grain", {{"density", kRho}, {"stiffness", k_grain}, {"restitution", 0.3}, {"reference_radius", 0.0045}}},
                      {"wall", {{"density", 7800.0}, {"stiffness", k_grain * ratio}, {"restitution", 0.3}, {"reference_radius", 0.0045}}}};
    c["time"] = {{"dt_per_contact_time", 0.04}, {"duration", 1.0}};
    c["output"] = {{"series_interval", 0.01}};
    const Outcome o = run(c, "stiffness_ratio");
    const double load = o.series.empty() ? NAN : -o.last("wall_fz") / weight - 1.0;
    const long steps = o.summary.empty() ? 0 : o.summary["run"]["steps"].get<long>();
    const double wall_s = o.summary.empty() ? NAN : o.summary["run"]["wall_seconds"].get<double>();
    std::snprintf(b, sizeof b, "| %g | %ld | %.1f | %+.2e | %.2e | %.3f | %+.2e | %s%s |", ratio, steps, wall_s, load,
                  o.series.empty() ? NAN : o.last("E_kin"), o.column_max("max_overlap_ratio"),
                  o.series.empty() ? NAN : o.last("rel_drift"), o.error.empty() ? "completed" : ("stopped: " + o.error).c_str(),
                  o.non_finite ? " — NON-FINITE VALUE IN RESULTS" : "");
    md.push_back(b);
    std::printf("%s\n", b);
    ratios.push_back({{"k_wall_over_k_grain", ratio}, {"k_grain", k_grain}, {"steps", steps}, {"wall_seconds", wall_s}, {"wall_load_over_weight_minus_1", load},
                      {"error", o.error}, {"non_finite_in_results", o.non_finite}});
  }
  report["stiffness_ratio"] = ratios;

  fs::create_directories(out);
  std::ofstream(out / "stress_runs.json") << std::setw(1) << report << "\n";
  std::ofstream f(out / "stress_runs.md");
  f << "# Stress runs\n\nWritten by `" << command << "` (bench/stress_runs.cpp): each run is a real "
       "`run_case` of a scene built in the program; the oracles are closed forms or the static weight balance.\n\n";
  for (const auto& line : md) f << line << "\n";
  return 0;
}
