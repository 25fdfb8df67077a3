// Benchmark (issue 5 §4): what each feature costs per step on the anchor scene, so that a scene
// pays only for what it uses. The anchor scene of tools/bench_dense.py (N polydisperse balls in a
// box of fixed wall balls, frictionless Kelvin–Voigt, clamped, velocity Verlet with the half-step
// dashpot) is settled once; from that dense bed every variant below runs STEPS steps, the variants
// interleaved REPEATS times so that a slow spell of this shared machine hits them all alike. The
// figure is the median in-process loop time per step (summary.json run.loop_seconds / steps: the step loop alone); the
// noise figure is the base variant's own spread (max − min)/median over its repeats.
//   build/bench/bench_feature_cost [OUT_DIR] [N] [STEPS] [REPEATS]   (defaults: reports 20000 2000 5)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "silodem/case/case_loader.hpp"
#include "silodem/core/parallel.hpp"
#include "silodem/run/simulation.hpp"

namespace fs = std::filesystem;
using nlohmann::json;
using namespace silodem;

namespace {

const fs::path kWork = fs::temp_directory_path() / "silodem_bench_feature_cost";
constexpr double kDt = 4e-5;

/// tools/bench_dense.py's scene(n): a loose 12 mm lattice of r 4.5–5.5 mm balls in a closed box of
/// r 5 mm wall balls on a 10 mm grid, about 25 × 25 balls per layer at N = 20,000.
json anchor_scene(int n) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> radius(0.0045, 0.0055);
  const int per_side = std::max(4, int(std::lround(25 * std::sqrt(n / 20000.0))));
  const int layers = (n + per_side * per_side - 1) / (per_side * per_side);
  const double inner = per_side * 0.012 + 0.02, height = layers * 0.012 + 0.05;
  json balls = json::array();
  auto wall = [&](double x, double y, double z) {
    balls.push_back({{"id", "w" + std::to_string(balls.size())}, {"material", "wall"}, {"radius", 0.005},
                     {"position", {x, y, z}}, {"fixed", true}});
  };
  const int m = int(std::lround(inner / 0.01)) + 1, h = int(std::lround(height / 0.01)) + 1;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      wall(-inner / 2 + i * 0.01, -inner / 2 + j * 0.01, 0.0);
      wall(-inner / 2 + i * 0.01, -inner / 2 + j * 0.01, (h - 1) * 0.01);
    }
  for (int k = 1; k < h - 1; ++k)
    for (int i = 0; i < m; ++i) {
      wall(-inner / 2 + i * 0.01, -inner / 2, k * 0.01);
      wall(-inner / 2 + i * 0.01, inner / 2, k * 0.01);
      if (0 < i && i < m - 1) {
        wall(-inner / 2, -inner / 2 + i * 0.01, k * 0.01);
        wall(inner / 2, -inner / 2 + i * 0.01, k * 0.01);
      }
    }
  for (int count = 0, k = 0; k < layers; ++k)
    for (int i = 0; i < per_side; ++i)
      for (int j = 0; j < per_side && count < n; ++j, ++count)
        balls.push_back({{"id", "b" + std::to_string(count)}, {"material", "grain"}, {"radius", radius(rng)},
                         {"position", {-inner / 2 + 0.016 + i * 0.012, -inner / 2 + 0.016 + j * 0.012, 0.016 + k * 0.012}}});
  const json mat = {{"density", 2500}, {"stiffness", 2e4}, {"damping", 2.2048}};
  return {{"format", "silodem-case/1"}, {"name", "feature_cost"}, {"seed", 1}, {"gravity", {0, 0, -9.81}},
          {"materials", {{"grain", mat}, {"wall", mat}}}, {"contact", {{"clamp_tensile_force", true}}},
          {"balls", balls}, {"integrator", {{"scheme", "velocity_verlet"}, {"dashpot_velocity", "half_step"}}},
          {"time", {{"dt", kDt}, {"duration", kDt * 10000}}}, {"neighbour", {{"skin", 0.001}}},
          {"output", {{"series_interval", 1.0}}}};
}

struct Variant {
  std::string name, what;
  std::function<void(json&)> patch;
  int threads = 1;
};

double seconds_per_step(const json& c, int threads, long steps) {
  set_threads(threads);
  const json s = run_case(load_case(c), {kWork / "run", false, false});
  set_threads(1);
  return s["run"]["loop_seconds"].get<double>() / double(steps);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

}  // namespace

int main(int argc, char** argv) {
  const fs::path out = argc > 1 ? argv[1] : "reports";
  const int n = argc > 2 ? std::stoi(argv[2]) : 20000;
  const long steps = argc > 3 ? std::stol(argv[3]) : 2000;
  const int repeats = argc > 4 ? std::stoi(argv[4]) : 5;
  fs::create_directories(kWork);

  // The dense bed: 10,000 steps of settling (not timed), then its state is the scene.
  json scene = anchor_scene(n);
  set_threads(2);
  run_case(load_case(scene), {kWork / "settled", false, false});
  set_threads(1);
  const json state = json::parse(std::ifstream(kWork / "settled" / "state.json"));
  json dense = scene;
  dense["balls"] = json::array();
  for (const auto& b : state["balls"]) {
    json d;
    for (const char* k : {"id", "material", "radius", "position", "velocity", "fixed"})
      if (b.contains(k)) d[k] = b[k];
    dense["balls"].push_back(d);
  }
  dense["time"] = {{"dt", kDt}, {"duration", kDt * double(steps) * (1 + 1e-9)}};
  std::size_t n_wall = 0;
  for (const auto& b : dense["balls"]) n_wall += b.value("fixed", false);

  const std::vector<Variant> variants = {
      {"base", "frictionless Kelvin–Voigt, dashpot on, clamped, velocity Verlet (half-step dashpot), no probes, "
               "energy ledger and guards (always on)", [](json&) {}},
      {"damping_off", "c = 0 (the dashpot is not compiled out: same loop, zero coefficient)",
       [](json& c) { c["materials"]["grain"]["damping"] = 0.0, c["materials"]["wall"]["damping"] = 0.0; }},
      {"unclamped", "contact.clamp_tensile_force false (a template parameter)",
       [](json& c) { c["contact"]["clamp_tensile_force"] = false; }},
      {"cohesion_on", "contact.cohesion {p_N 0.1} (9)–(10): a template parameter; pairs within the cohesion reach also count",
       [](json& c) { c["contact"]["cohesion"] = {{"p_N", 0.1}}; }},
      {"onset_correction_on", "contact.onset_correction true (a template parameter)",
       [](json& c) { c["contact"]["onset_correction"] = true; }},
      {"probes_on", "20 ball probes and a pair probe, series.csv every step",
       [](json& c) {
         json probes = {{{"type", "pair"}, {"name", "two"}, {"balls", {"b0", "b1"}}}};
         for (int i = 0; i < 20; ++i)
           probes.push_back({{"type", "ball"}, {"name", "ball" + std::to_string(i)}, {"balls", {"b" + std::to_string(i * 97)}}});
         c["output"] = {{"series_interval", kDt * 0.999}, {"probes", probes}};
       }},
      {"stop_tests_every_step", "equilibrium (27)–(29) tested every step (it never stops this run)",
       [](json& c) { c["equilibrium"] = {{"p_f", 1e-12}, {"p_ft", 1e-12}, {"check_interval_steps", 1}}; }},
      {"extra_fixed_balls", "20,000 more fixed balls in a touching slab 1 m below the box: fixed balls are not "
                            "integrated and wall–wall pairs are never listed",
       [](json& c) {
         for (int i = 0; i < 200; ++i)
           for (int j = 0; j < 100; ++j)
             c["balls"].push_back({{"id", "slab" + std::to_string(i * 100 + j)}, {"material", "wall"}, {"radius", 0.005},
                                   {"position", {-1.0 + i * 0.01, -0.5 + j * 0.01, -1.0}}, {"fixed", true}});
       }},
      {"predictor_corrector_m1", "the paper's explicit predictor–corrector instead of Verlet",
       [](json& c) { c["integrator"] = {{"scheme", "predictor_corrector"}, {"max_corrector_passes", 1}}; }},
      {"friction_history", "contact.tangential linear_history, mu = 0.5, k_t = 2/7 k_n: rotation, the frictional "
                           "law (forces/frictional_field.cpp) and the contact history",
       [](json& c) {
         c["contact"]["tangential"] = "linear_history";
         for (auto& [name, m] : c["materials"].items()) m["friction"] = 0.5;
       }},
      {"friction_history_rolling", "friction_history and contact.rolling constant_torque, mu_r = 0.02",
       [](json& c) {
         c["contact"]["tangential"] = "linear_history";
         c["contact"]["rolling"] = "constant_torque";
         for (auto& [name, m] : c["materials"].items()) m["friction"] = 0.5, m["rolling_friction"] = 0.02;
       }},
      {"rolling_only", "contact.rolling constant_torque alone, mu_r = 0.02: rotation without a tangential force",
       [](json& c) {
         c["contact"]["rolling"] = "constant_torque";
         for (auto& [name, m] : c["materials"].items()) m["rolling_friction"] = 0.02;
       }},
      {"hertz", "contact.normal hertz, no friction: E = 6e7 Pa, nu = 0.3, e = 0.5 (about the base stiffness at "
                "1e-5 m of overlap); the frictional law class without rotation",
       [](json& c) {
         c["contact"]["normal"] = "hertz";
         const json mat = {{"density", 2500}, {"youngs_modulus", 6e7}, {"poisson_ratio", 0.3}, {"restitution", 0.5}};
         c["materials"] = {{"grain", mat}, {"wall", mat}};
       }},
      {"coulomb_sliding", "contact.tangential coulomb_sliding, mu = 0.5, gamma_t = 2.2 N s/m (the seeds' law: no "
                          "history): rotation and the sliding force",
       [](json& c) {
         c["contact"]["tangential"] = "coulomb_sliding";
         for (auto& [name, m] : c["materials"].items()) m["friction"] = 0.5, m["tangential_damping"] = 2.2;
       }},
      {"friction_history_epsd", "friction_history and contact.rolling epsd, mu_r = 0.02: a second spring in the history",
       [](json& c) {
         c["contact"]["tangential"] = "linear_history";
         c["contact"]["rolling"] = "epsd";
         for (auto& [name, m] : c["materials"].items()) m["friction"] = 0.5, m["rolling_friction"] = 0.02;
       }},
      {"hertz_mindlin", "hertz with contact.tangential mindlin, mu = 0.5 (k_t = 8 G* sqrt(R* delta), with history)",
       [](json& c) {
         c["contact"]["normal"] = "hertz";
         c["contact"]["tangential"] = "mindlin";
         const json mat = {{"density", 2500}, {"youngs_modulus", 6e7}, {"poisson_ratio", 0.3}, {"restitution", 0.5},
                           {"friction", 0.5}};
         c["materials"] = {{"grain", mat}, {"wall", mat}};
       }},
      {"threads_2", "the base scene on 2 threads", [](json&) {}, 2},
      {"friction_history_threads_2", "friction_history on 2 threads",
       [](json& c) {
         c["contact"]["tangential"] = "linear_history";
         for (auto& [name, m] : c["materials"].items()) m["friction"] = 0.5;
       },
       2},
  };
  std::map<std::string, std::vector<double>> t;
  for (int rep = 0; rep < repeats; ++rep)
    for (const auto& v : variants) {
      json c = dense;
      v.patch(c);
      t[v.name].push_back(seconds_per_step(c, v.threads, steps));
      std::fprintf(stderr, "[feature_cost] repeat %d/%d %-24s %.3f ms/step\n", rep + 1, repeats, v.name.c_str(), 1e3 * t[v.name].back());
    }
  const double base = median(t["base"]);
  const auto [lo, hi] = std::minmax_element(t["base"].begin(), t["base"].end());
  const double noise = (*hi - *lo) / base;
  json rows = json::array();
  char b[1024];
  std::string md = "| variant | what | ms per step (median) | Mps/s | / base − 1 |\n|---|---|---|---|---|\n";
  for (const auto& v : variants) {
    const double m = median(t[v.name]);
    rows.push_back({{"variant", v.name}, {"what", v.what}, {"threads", v.threads}, {"seconds_per_step", t[v.name]},
                    {"median_seconds_per_step", m}, {"ratio_to_base", m / base}});
    std::snprintf(b, sizeof b, "| %s | %s | %.3f | %.2f | %+.1f %% |\n", v.name.c_str(), v.what.c_str(), 1e3 * m,
                  double(n) / m / 1e6, 100.0 * (m / base - 1.0));
    md += b;
    std::printf("%-24s %8.3f ms/step %+6.1f %%\n", v.name.c_str(), 1e3 * m, 100.0 * (m / base - 1.0));
  }
  fs::create_directories(out);
  std::ofstream(out / "feature_cost.json") << std::setw(1)
                                            << json{{"command", "build/bench/bench_feature_cost reports " + std::to_string(n) + " " +
                                                                    std::to_string(steps) + " " + std::to_string(repeats)},
                                                    {"mobile", n}, {"wall", n_wall}, {"steps", steps}, {"repeats", repeats},
                                                    {"base_spread", noise}, {"rows", rows}}
                                            << "\n";
  std::ofstream f(out / "feature_cost.md");
  std::snprintf(b, sizeof b,
                "# What each feature costs\n\nWritten by `build/bench/bench_feature_cost reports %d %ld %d` "
                "(bench/feature_cost.cpp). The anchor scene (tools/bench_dense.py: %d mobile balls, %zu wall balls), "
                "settled for 10,000 steps, then %ld steps per run, the variants interleaved %d times; median in-process "
                "loop time per step, 1 thread unless stated. Noise: the base variant's own spread over its repeats is "
                "%.1f %% of its median — a difference smaller than that is not a measured cost.\n\n",
                n, steps, repeats, n, n_wall, steps, repeats, 100.0 * noise);
  f << b << md
    << "\nCohesion, clamping and the onset correction are template parameters of the force loop "
       "(forces/force_field.cpp, make_force_field): a scene without them runs the loop compiled without "
       "them, so 'off' is the build without the feature. The dashpot, the energy ledger and the guards are "
       "not compiled out; the damping_off row shows what a zero coefficient saves.\n";
  return 0;
}
