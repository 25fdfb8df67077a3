// Determinism across thread counts (core/parallel.hpp): a dense polydisperse bed settling in a box
// of wall balls, run with 1 and with 2 threads, must end in bitwise the same state — positions,
// velocities, the wall load and the energy ledger — since every sum over pairs or balls has a fixed
// order. One thread takes the force loop's one pass, two threads its ranges (each gathering the
// reactions from the range below and storing its wall pairs);
// the bed spans several of the chunks (kSumChunk balls) that the loops hand out.
#include <gtest/gtest.h>

#include <filesystem>
#include <random>

#include "silodem/case/case_loader.hpp"
#include "silodem/core/parallel.hpp"
#include "silodem/output/state_file.hpp"
#include "silodem/run/simulation.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json settling_bed() {
  json balls = json::array();
  int n = 0;
  const double s = 0.008;
  for (int i = -8; i <= 8; ++i)
    for (int j = -8; j <= 8; ++j) {
      balls.push_back({{"id", "w" + std::to_string(n++)}, {"material", "g"}, {"radius", 0.005}, {"position", {i * s, j * s, 0.0}}, {"fixed", true}});
      for (int k = 1; k <= 10 && (std::abs(i) == 8 || std::abs(j) == 8); ++k)
        balls.push_back({{"id", "w" + std::to_string(n++)}, {"material", "g"}, {"radius", 0.005}, {"position", {i * s, j * s, k * s}}, {"fixed", true}});
    }
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> r(0.003, 0.004);
  for (int i = -6; i <= 6; ++i)
    for (int j = -6; j <= 6; ++j)
      for (int k = 0; k < 7; ++k)
        balls.push_back({{"id", "b" + std::to_string(n++)}, {"material", "g"}, {"radius", r(rng)},
                         {"position", {i * 0.0085, j * 0.0085, 0.01 + k * 0.0085}}});
  return {{"name", "threads"}, {"seed", 1},
          {"materials", {{"g", {{"density", 2500}, {"stiffness", 1e5}, {"damping_ratio", 0.3}, {"reference_radius", 0.0035}}}}},
          {"balls", balls},
          {"integrator", {{"scheme", "predictor_corrector"}, {"max_corrector_passes", 3}}},
          {"time", {{"dt", 2e-5}, {"duration", 0.15}}}};
}

struct Outcome {
  silodem::StateSnapshot state;
  json summary;
};

Outcome run_with(int threads, const silodem::CaseConfig& cfg) {
  silodem::set_threads(threads);
  const fs::path out = fs::temp_directory_path() / ("silodem_threads_" + std::to_string(threads));
  json summary = silodem::run_case(cfg, {out, false, false});
  silodem::set_threads(1);
  auto s = silodem::read_state(out / "state.json");
  fs::remove_all(out);
  return {std::move(s), std::move(summary)};
}

}  // namespace

TEST(Threads, OneAndTwoThreadsGiveBitwiseTheSameState) {
  silodem::set_threads(2);
  if (silodem::threads() < 2) GTEST_SKIP() << "built without OpenMP: one thread only";
  const silodem::CaseConfig cfg = silodem::load_case(settling_bed());
  const auto ra = run_with(1, cfg), rb = run_with(2, cfg);
  const auto& a = ra.state;
  const auto& b = rb.state;
  ASSERT_GT(cfg.balls.size() - 17 * 17 - 4 * 16 * 10, 2 * silodem::kSumChunk);  // mobile balls: several chunks
  ASSERT_EQ(a.balls.size(), b.balls.size());
  EXPECT_EQ(ra.summary["wall_force"], rb.summary["wall_force"]);
  for (const char* term : {"kinetic", "gravitational", "elastic", "dissipated", "balance"})
    EXPECT_EQ(ra.summary["energy"][term].get<double>(), rb.summary["energy"][term].get<double>()) << term;
  double moved = 0.0;
  for (std::size_t i = 0; i < a.balls.size(); ++i) {
    for (int d = 0; d < 3; ++d) {
      EXPECT_EQ(a.balls[i].position[d], b.balls[i].position[d]) << a.balls[i].id;  // bitwise, not near
      EXPECT_EQ(a.balls[i].velocity[d], b.balls[i].velocity[d]) << a.balls[i].id;
    }
    moved = std::max(moved, std::abs(a.balls[i].velocity.z()));
  }
  EXPECT_GT(moved, 0.01);  // the bed was still moving: the state is not trivially at rest
}

TEST(Threads, OneAndTwoThreadsGiveBitwiseTheSameStateWithFriction) {
  // The same bed with a history spring, rolling resistance and the multiple corrector: each pass
  // is a trial from the committed springs (forces/contact_history.hpp), and the pair pass of the
  // frictional loop writes per-slot results gathered per ball in a fixed order.
  silodem::set_threads(2);
  if (silodem::threads() < 2) GTEST_SKIP() << "built without OpenMP: one thread only";
  json c = settling_bed();
  c["name"] = "threads_friction";
  c["contact"] = {{"tangential", "linear_history"}, {"rolling", "constant_torque"}};
  c["materials"]["g"]["friction"] = 0.5;
  c["materials"]["g"]["rolling_friction"] = 0.05;
  c["materials"]["g"]["tangential_damping_ratio"] = 0.5;
  c["time"]["duration"] = 0.04;
  const silodem::CaseConfig cfg = silodem::load_case(c);
  const auto ra = run_with(1, cfg), rb = run_with(2, cfg);
  ASSERT_EQ(ra.state.balls.size(), rb.state.balls.size());
  EXPECT_EQ(ra.summary["wall_force"], rb.summary["wall_force"]);
  for (const char* term : {"kinetic", "rotational", "elastic", "elastic_tangential", "friction_dissipated", "balance"})
    EXPECT_EQ(ra.summary["energy"][term].get<double>(), rb.summary["energy"][term].get<double>()) << term;
  double spin = 0.0;
  for (std::size_t i = 0; i < ra.state.balls.size(); ++i)
    for (int d = 0; d < 3; ++d) {
      EXPECT_EQ(ra.state.balls[i].position[d], rb.state.balls[i].position[d]) << ra.state.balls[i].id;
      EXPECT_EQ(ra.state.balls[i].velocity[d], rb.state.balls[i].velocity[d]) << ra.state.balls[i].id;
      EXPECT_EQ(ra.state.balls[i].angular_velocity[d], rb.state.balls[i].angular_velocity[d]) << ra.state.balls[i].id;
      spin = std::max(spin, std::abs(ra.state.balls[i].angular_velocity[d]));
    }
  EXPECT_GT(spin, 1.0);  // the balls do turn: friction acted
  EXPECT_GT(ra.summary["energy"]["friction_dissipated"].get<double>(), 0.0);
  // The ledger closes with the friction terms: a term left out would be of the order of the
  // energy moved (drift ~1), the trapezoid rule's own error is far below 1e-2.
  EXPECT_LT(std::abs(ra.summary["energy"]["max_abs_relative_drift"].get<double>()), 1e-2);
}
