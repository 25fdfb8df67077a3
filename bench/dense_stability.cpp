// Benchmark (issue 5 §3): the largest stable time step in a dense packing, against the highest
// natural frequency of that packing, and what the run guards do when the step is too large.
//
// The scene: an FCC block of equal balls, every nearest-neighbour pair overlapping by 2ε r,
// caged by fixed wall balls on the lattice sites around it, no gravity, so the block is in
// equilibrium; a tiny velocity along the top mode keeps every contact closed: the motion is linear,
// M ü + C u̇ + K u = 0. The oracle is K's largest eigenvalue, computed here from the contact
// network with Eigen (normal stiffness k n nᵀ and the geometric term −(f/d)(I − n nᵀ) of each
// pre-loaded pair): ω_max = √(λ_max/m). Every scheme's limit on one contact (docs/theory.md §7,
// bench_stability) then carries over mode by mode: Ω_pair = ω_pair Δt must satisfy
// Ω_pair ≤ Ω_1(ζ_max) · ω_pair/ω_max, where the dashpot, being c/k times the normal stiffness,
// damps the top mode with ζ_top = ζ_pair · (vᵀK_n v/m)/(ω_pair ω_max), v the top eigenvector and K_n
// the normal part of K (≈ ζ_pair ω_max/ω_pair: the geometric term is ~1 %).
//
// Each trial is a real `run_case` of the block for `steps` steps; unstable means a guard stopped
// it or the kinetic energy rose above ten times its start. The guards' energy test is relaxed during the
// search (a stable Verlet run near its limit swings its energy widely) and a final run at 1.1 ×
// the measured limit with the default guards shows the clean stop: which guard, and that no
// result file holds NaN or inf.
//   build/bench/bench_dense_stability [OUT_DIR]     (default: reports)
//   build/bench/bench_dense_stability --case SCHEME ZETA OMEGA_DT FILE.json   (one trial's case)
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "silodem/case/case_loader.hpp"
#include "silodem/integrate/stability.hpp"
#include "silodem/run/simulation.hpp"

namespace fs = std::filesystem;
using nlohmann::json;
using namespace silodem;

namespace {

constexpr int kCells = 8;            // FCC sites (i,j,k), i+j+k even, 0..kCells: 365 mobile balls
constexpr double kH = 0.005;         // half the cubic cell: nearest neighbours at kH √2
constexpr double kEps = 0.01;        // overlap 2 ε r on every pair
constexpr double kDensity = 2500.0, kStiffness = 2e4;  // per ball; a pair of equal balls: k/2 (11)
const double kRadius = kH * std::sqrt(2.0) / 2.0 / (1.0 - kEps);
const double kMass = kDensity * 4.0 / 3.0 * M_PI * kRadius * kRadius * kRadius;
const double kPairK = kStiffness / 2.0;
const double kOmegaPair = std::sqrt(kPairK / (kMass / 2.0));  // the stiffest pair: two mobile balls

struct Block {
  std::vector<Eigen::Vector3d> mobile, wall;
};

Block fcc_block() {
  Block b;
  auto inside = [](int i, int j, int k) { return i >= 0 && j >= 0 && k >= 0 && i <= kCells && j <= kCells && k <= kCells; };
  for (int i = -1; i <= kCells + 1; ++i)
    for (int j = -1; j <= kCells + 1; ++j)
      for (int k = -1; k <= kCells + 1; ++k) {
        if ((i + j + k) % 2 != 0) continue;
        const Eigen::Vector3d x(i * kH, j * kH, k * kH);
        if (inside(i, j, k)) {
          b.mobile.push_back(x);
          continue;
        }
        bool touches = false;  // a wall site is kept only if it is a nearest neighbour of a mobile site
        for (int di = -1; di <= 1 && !touches; ++di)
          for (int dj = -1; dj <= 1 && !touches; ++dj)
            for (int dk = -1; dk <= 1 && !touches; ++dk)
              if (std::abs(di) + std::abs(dj) + std::abs(dk) == 2 && inside(i + di, j + dj, k + dk)) touches = true;
        if (touches) b.wall.push_back(x);
      }
  return b;
}

struct TopMode {
  double omega;           // ω_max = √(λ_max(K)/m)
  double two_zeta_omega;  // vᵀ C v / m for the normalised top eigenvector v, with C = (c/k) K_normal per unit c/k
  Eigen::VectorXd shape;  // v
};

/// The top mode of the block's contact network.
TopMode top_mode(const Block& b) {
  const int n = int(b.mobile.size());
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(3 * n, 3 * n), Kn = K;
  const double reach = 2.0 * kRadius;
  auto normal_block = [&](const Eigen::Vector3d& xi, const Eigen::Vector3d& xj) {
    const Eigen::Vector3d nn = (xi - xj).normalized();
    return Eigen::Matrix3d(kPairK * nn * nn.transpose());
  };
  auto pair_block = [&](const Eigen::Vector3d& xi, const Eigen::Vector3d& xj) {
    const Eigen::Vector3d d = xi - xj;
    const double len = d.norm();
    const Eigen::Vector3d nn = d / len;
    const double f = kPairK * (reach - len);
    return Eigen::Matrix3d(normal_block(xi, xj) - (f / len) * (Eigen::Matrix3d::Identity() - nn * nn.transpose()));
  };
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j)
      if ((b.mobile[i] - b.mobile[j]).norm() < reach) {
        for (auto* M : {&K, &Kn}) {
          const Eigen::Matrix3d B = M == &K ? pair_block(b.mobile[i], b.mobile[j]) : normal_block(b.mobile[i], b.mobile[j]);
          M->block<3, 3>(3 * i, 3 * i) += B;
          M->block<3, 3>(3 * j, 3 * j) += B;
          M->block<3, 3>(3 * i, 3 * j) -= B;
          M->block<3, 3>(3 * j, 3 * i) -= B;
        }
      }
    for (const auto& w : b.wall)
      if ((b.mobile[i] - w).norm() < reach) {
        K.block<3, 3>(3 * i, 3 * i) += pair_block(b.mobile[i], w);
        Kn.block<3, 3>(3 * i, 3 * i) += normal_block(b.mobile[i], w);
      }
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(K);
  const Eigen::Index top = 3 * n - 1;  // eigenvalues come sorted ascending
  const Eigen::VectorXd v = es.eigenvectors().col(top);
  return {std::sqrt(es.eigenvalues()(top) / kMass), v.dot(Kn * v) / kMass, v};
}

json block_case(const Block& b, const Eigen::VectorXd& shape, const json& integrator, double zeta_pair, double omega_dt, int steps, double drift_guard) {
  // Pair damping ratio ζ = c_pair/(2√(k_pair m_eff)); per ball c = 2 c_pair (series, (11)).
  const double c_ball = 2.0 * zeta_pair * 2.0 * std::sqrt(kPairK * kMass / 2.0);
  json balls = json::array();
  // The top mode alone is set moving, small enough that every contact stays closed (linear motion),
  // so growth or decay of that one mode decides the trial quickly.
  const double v0 = 1e-4 * 2.0 * kEps * kRadius * kOmegaPair / shape.cwiseAbs().maxCoeff();
  for (size_t i = 0; i < b.mobile.size(); ++i)
    balls.push_back({{"id", "m" + std::to_string(i)}, {"material", "grain"}, {"radius", kRadius},
                     {"position", {b.mobile[i].x(), b.mobile[i].y(), b.mobile[i].z()}},
                     {"velocity", {v0 * shape(3 * i), v0 * shape(3 * i + 1), v0 * shape(3 * i + 2)}}});
  for (size_t i = 0; i < b.wall.size(); ++i)
    balls.push_back({{"id", "w" + std::to_string(i)}, {"material", "grain"}, {"radius", kRadius},
                     {"position", {b.wall[i].x(), b.wall[i].y(), b.wall[i].z()}}, {"fixed", true}});
  const double dt = omega_dt / kOmegaPair;
  json c = {{"format", "silodem-case/1"}, {"name", "dense_stability"}, {"seed", 1}, {"gravity", {0.0, 0.0, 0.0}},
            {"materials", {{"grain", {{"density", kDensity}, {"stiffness", kStiffness}, {"damping", c_ball}}}}},
            {"balls", balls}, {"integrator", integrator},
            {"time", {{"dt", dt}, {"duration", dt * steps * (1.0 + 1e-9)}}},
            {"output", {{"series_interval", dt * 7}}}};
  if (drift_guard > 0) c["guards"] = {{"max_energy_drift", drift_guard}};
  return c;
}

struct Trial {
  bool stable = true;
  std::string guard;  // the RunError text, if one stopped the run
  bool nan_in_results = false;
};

bool file_has_non_finite(const fs::path& f) {
  std::ifstream in(f);
  const std::string s((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const char* bad : {"nan", "NaN", "inf", "Inf"})
    if (s.find(bad) != std::string::npos) return true;
  return false;
}

Trial run_trial(const json& c, const fs::path& out) {
  Trial t;
  fs::remove_all(out);
  fs::remove_all(out.string() + ".failed");
  try {
    run_case(load_case(c), {out, false, false});
  } catch (const RunError& e) {
    t.stable = false;
    t.guard = e.what();
    for (const char* f : {"summary.json", "series.csv", "state.json"})
      if (fs::exists(out.string() + ".failed/" + f)) t.nan_in_results |= file_has_non_finite(out.string() + ".failed/" + f);
    return t;
  }
  // The run starts with the top mode's velocity and no strain in it, so a stable run never holds
  // more kinetic energy than at the start (Verlet's discrete invariant v² + ω²(1 − Ω²/4)u²; damping
  // only lowers it); an unstable one grows until contacts open, ~10⁹-fold. Sampled every 7 steps.
  std::ifstream s(out / "series.csv");
  std::string line;
  std::getline(s, line);
  double first = -1, peak = 0;
  while (std::getline(s, line)) {
    std::stringstream ss(line);
    std::string t0, e;
    std::getline(ss, t0, ',');
    std::getline(ss, e, ',');
    if (first < 0) first = std::stod(e);
    peak = std::max(peak, std::stod(e));
  }
  t.stable = !(peak > 10.0 * first);
  return t;
}

struct Scheme_ {
  std::string name;
  json integrator;
  IntegratorSpec spec;
};

}  // namespace

int main(int argc, char** argv) {
  const fs::path out = argc == 2 ? argv[1] : "reports";
  const fs::path work = fs::temp_directory_path() / "silodem_bench_dense_stability";
  const int steps = 3000;
  const Block block = fcc_block();
  const TopMode top = top_mode(block);
  const double ratio = top.omega / kOmegaPair;
  // ζ_top per unit ζ_pair: 2 ζ_top ω_max = (c/k) vᵀK_n v/m and c/k = 2 ζ_pair/ω_pair.
  const double zeta_gain = top.two_zeta_omega / (kOmegaPair * top.omega);
  std::printf("FCC block: %zu mobile, %zu wall balls; omega_max/omega_pair = %.4f (Eigen, %zu x %zu)\n",
              block.mobile.size(), block.wall.size(), ratio, 3 * block.mobile.size(), 3 * block.mobile.size());
  std::vector<Scheme_> schemes;
  {
    IntegratorSpec s;
    s.scheme = Scheme::VelocityVerlet;
    s.half_step_dashpot = true;
    schemes.push_back({"velocity_verlet_half_step", {{"scheme", "velocity_verlet"}, {"dashpot_velocity", "half_step"}}, s});
    s.half_step_dashpot = false;
    schemes.push_back({"velocity_verlet", {{"scheme", "velocity_verlet"}}, s});
    IntegratorSpec p;
    p.max_corrector_passes = 1;
    schemes.push_back({"predictor_corrector_m1", {{"scheme", "predictor_corrector"}, {"max_corrector_passes", 1}}, p});
    p.max_corrector_passes = 3;
    schemes.push_back({"predictor_corrector_m3", {{"scheme", "predictor_corrector"}, {"max_corrector_passes", 3}}, p});
  }
  // One-contact limits Ω_1(ζ) of docs/theory.md §7 (bench_stability measured them within 0.1 %).
  auto one_contact = [](const std::string& name, double z) {
    if (name == "velocity_verlet_half_step") return 2.0 * (std::sqrt(1 + z * z) - z);
    if (name == "velocity_verlet") return 2.0 * (std::sqrt(1 + 4 * z * z) - 2 * z);
    if (z != 0.0) return double(NAN);  // docs/theory.md §7.4 gives the corrector's limits undamped only
    return name == "predictor_corrector_m1" ? 2.0 : 2.185;
  };
  json rows = json::array();
  if (argc == 6 && std::string(argv[1]) == "--case") {  // write one trial's case, to rerun it by hand
    for (const auto& s : schemes)
      if (s.name == argv[2]) {
        std::ofstream(argv[5]) << block_case(block, top.shape, s.integrator, std::stod(argv[3]), std::stod(argv[4]), steps, 1e3);
        return 0;
      }
    std::fprintf(stderr, "unknown scheme %s\n", argv[2]);
    return 2;
  }
  std::printf("%-26s %5s %9s %9s %9s %8s  %s\n", "scheme", "zeta", "measured", "theory", "loader", "dev", "guard at 1.1 x limit");
  for (const auto& s : schemes)
    for (const double zeta : {0.0, 0.1}) {
      const double loader = stable_time_step(s.spec, 1.0, zeta).dt_max;
      auto is_stable = [&](double om) { return run_trial(block_case(block, top.shape, s.integrator, zeta, om, steps, 1e3), work / "trial").stable; };
      // Bisection between a stable point and the loader's limit (the loader refuses anything above).
      double lo = 0.05, hi = loader * 0.9999;
      if (is_stable(hi)) lo = hi;
      while (hi - lo > 1e-4 && lo != hi) {
        const double mid = 0.5 * (lo + hi);
        (is_stable(mid) ? lo : hi) = mid;
      }
      const double zeta_top = zeta * zeta_gain;
      const double theory = one_contact(s.name, zeta_top) / ratio;
      // The same scheme just past its limit, default guards: how does the run end?
      Trial past;
      double past_omega = std::min(lo * 1.1, loader * 0.9999);
      if (past_omega > lo * 1.0001) past = run_trial(block_case(block, top.shape, s.integrator, zeta, past_omega, steps, 0.0), work / "past");
      const double dev = std::isfinite(theory) ? lo / theory - 1.0 : NAN;
      const std::string first_line = past.guard.substr(0, past.guard.find('\n'));
      std::printf("%-26s %5.2f %9.4f %9.4f %9.4f %+7.2f%%  %s%s\n", s.name.c_str(), zeta, lo, theory, loader, 100 * dev,
                  past.stable ? "(no instability reached)" : first_line.substr(0, 90).c_str(),
                  past.nan_in_results ? " [NaN IN RESULTS]" : "");
      rows.push_back({{"scheme", s.name}, {"zeta_pair", zeta}, {"zeta_top_mode", zeta_top}, {"measured_omega_dt", lo},
                      {"theory_omega_dt", std::isfinite(theory) ? json(theory) : json(nullptr)}, {"loader_omega_dt", loader},
                      {"past_limit_omega_dt", past_omega}, {"past_limit_stopped_by", first_line},
                      {"past_limit_non_finite_in_results", past.nan_in_results}});
    }
  fs::create_directories(out);
  std::ofstream(out / "dense_stability.json")
      << std::setw(1)
      << json{{"what", "largest stable omega_pair*dt in a caged FCC block against its highest natural frequency"},
              {"command", "build/bench/bench_dense_stability reports"}, {"mobile", block.mobile.size()},
              {"wall", block.wall.size()}, {"omega_max_over_omega_pair", ratio}, {"steps_per_trial", steps}, {"rows", rows}}
      << "\n";
  std::ofstream md(out / "dense_stability.md");
  char b[2048];
  std::snprintf(b, sizeof b,
                "# Stability limits in a dense packing\n\nWritten by `build/bench/bench_dense_stability reports` "
                "(bench/dense_stability.cpp). An FCC block of %zu equal balls (r = %.3f mm, every nearest-neighbour pair "
                "overlapping by 2 %% of r, 12 contacts each) caged by %zu fixed wall balls on the lattice sites around it, "
                "no gravity, a tiny velocity along the top mode so every contact stays closed. Oracle: the contact network's largest "
                "stiffness eigenvalue (Eigen, normal and geometric terms): ω_max/ω_pair = %.4f. A scheme whose one-contact "
                "limit is Ω_1(ζ) (docs/theory.md §7) is stable here up to ω_pair Δt = Ω_1(ζ_top)·ω_pair/ω_max, with the top "
                "mode's damping ratio ζ_top = ζ_pair·(vᵀK_n v/m)/(ω_pair ω_max) ≈ ζ_pair·ω_max/ω_pair (the dashpot is c/k "
                "times the normal stiffness K_n; v the top eigenvector). "
                "Measured by bisection to 1e-4 on real runs of %d steps (unstable: a guard stopped the run, or the kinetic "
                "energy rose above ten times its start, which a stable run never does from this start). The loader's limit is the one-contact limit for the stiffest pair — necessary, "
                "not sufficient, as this table shows: between the two limits only the run guards protect a run. The "
                "last column is a run at 1.1 × the measured limit with the default guards.\n\n",
                block.mobile.size(), kRadius * 1e3, block.wall.size(), ratio, steps);
  md << b << "| scheme | ζ_pair | ζ_top | measured ω_pair Δt | theory | loader refuses above | measured/theory − 1 | at 1.1 × the limit |\n|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows) {
    char th[32] = "—", dev[32] = "—";
    if (!r["theory_omega_dt"].is_null()) {
      std::snprintf(th, sizeof th, "%.4f", r["theory_omega_dt"].get<double>());
      std::snprintf(dev, sizeof dev, "%+.2f %%", 100 * (r["measured_omega_dt"].get<double>() / r["theory_omega_dt"].get<double>() - 1));
    }
    std::string past = r["past_limit_stopped_by"].get<std::string>();
    past = past.substr(0, past.find(" [last state"));  // the path is of a temporary directory
    for (size_t at = past.find('|'); at != std::string::npos; at = past.find('|', at + 2)) past.replace(at, 1, "\\|");
    if (past.empty()) past = "no guard tripped";
    if (r["past_limit_non_finite_in_results"].get<bool>()) past += " — NON-FINITE VALUES IN RESULTS";
    std::snprintf(b, sizeof b, "| %s | %.1f | %.3f | %.4f | %s | %.4f | %s | %s |\n", r["scheme"].get<std::string>().c_str(),
                  r["zeta_pair"].get<double>(), r["zeta_top_mode"].get<double>(), r["measured_omega_dt"].get<double>(), th,
                  r["loader_omega_dt"].get<double>(), dev, past.c_str());
    md << b;
  }
  return 0;
}
