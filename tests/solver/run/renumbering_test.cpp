// Renumbering the mobile balls (neighbour/spatial_order.hpp, between steps in run/simulation.cpp)
// changes indices, never physics: a settling bed renumbered before every step must follow the same
// trajectories as one never renumbered, up to the rounding of sums taken in another order. The
// oracle is the run without renumbering. A renumbering that forgot a piece of per-ball state (ü of
// the integrator, say) would hand one ball's acceleration to another: millimetres, not rounding.
#include <gtest/gtest.h>

#include <filesystem>
#include <random>

#include "silodem/case/case_loader.hpp"
#include "silodem/output/state_file.hpp"
#include "silodem/run/simulation.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json bed(const std::string& scheme, long sort_interval) {
  json balls = json::array();
  int n = 0;
  const double s = 0.008;
  for (int i = -5; i <= 5; ++i)
    for (int j = -5; j <= 5; ++j)
      balls.push_back({{"id", "w" + std::to_string(n++)}, {"material", "g"}, {"radius", 0.005}, {"position", {i * s, j * s, 0.0}}, {"fixed", true}});
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> r(0.003, 0.004), jitter(-0.0004, 0.0004);
  for (int i = -4; i <= 4; ++i)
    for (int j = -4; j <= 4; ++j)
      for (int k = 0; k < 4; ++k)
        balls.push_back({{"id", "b" + std::to_string(n++)}, {"material", "g"}, {"radius", r(rng)},
                         {"position", {i * 0.0085 + jitter(rng), j * 0.0085 + jitter(rng), 0.01 + k * 0.0085}}});
  return {{"name", "renumbering"}, {"seed", 1},
          {"materials", {{"g", {{"density", 2500}, {"stiffness", 1e5}, {"damping_ratio", 0.3}, {"reference_radius", 0.0035}}}}},
          {"balls", balls},
          {"integrator", {{"scheme", scheme}}},
          {"neighbour", {{"sort_interval_steps", sort_interval}}},
          {"time", {{"dt", 2e-5}, {"duration", 0.02}}}};
}

silodem::StateSnapshot run(const json& c, const std::string& tag) {
  const fs::path out = fs::temp_directory_path() / ("silodem_renumbering_" + tag);
  silodem::run_case(silodem::load_case(c), {out, false, false});
  auto s = silodem::read_state(out / "state.json");
  fs::remove_all(out);
  return s;
}

}  // namespace

TEST(Renumbering, EveryStepChangesNoTrajectoryBeyondRounding) {
  for (const std::string scheme : {"velocity_verlet", "predictor_corrector"}) {
    const auto never = run(bed(scheme, 0), scheme + "_never");
    const auto every = run(bed(scheme, 1), scheme + "_every");
    ASSERT_EQ(never.balls.size(), every.balls.size());
    double dx = 0.0, fall = 0.0;
    for (std::size_t i = 0; i < never.balls.size(); ++i) {
      ASSERT_EQ(never.balls[i].id, every.balls[i].id);  // states list balls in tag order
      dx = std::max(dx, (never.balls[i].position - every.balls[i].position).norm());
      fall = std::max(fall, std::abs(never.balls[i].velocity.z()));
    }
    EXPECT_GT(fall, 0.05) << scheme;  // the bed was moving and colliding, not at rest
    EXPECT_LT(dx, 1e-10) << scheme << ": positions differ by " << dx << " m";
  }
}
