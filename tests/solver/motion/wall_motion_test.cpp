// Moving walls (a move_wall event): a wall ball set moving at V hits a grain at rest, which leaves
// at 2V (undamped linear contact: in the wall's frame an elastic rebound off an immovable body); the
// wall travels V t exactly, the neighbour list sees it come (it starts far beyond the skin), and its
// work, ½ m (2V)², enters the ledger so that the balance closes.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "../case_runs.hpp"
#include "silodem/case/case_error.hpp"
#include "silodem/case/case_loader.hpp"
#include "silodem/run/simulation.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

using silodem_test::refusal;

namespace {

constexpr double kV = 0.5, kR = 0.005, kDensity = 2500.0;

json piston_case() {
  return {{"name", "piston"},
          {"gravity", {0, 0, 0}},
          {"materials", {{"grain", {{"density", kDensity}, {"stiffness", 2e5}, {"damping", 0.0}}}}},
          {"balls",
           {{{"id", "ball"}, {"material", "grain"}, {"radius", kR}, {"position", {0, 0, 0}}},
            {{"id", "piston"}, {"material", "grain"}, {"radius", kR}, {"position", {-0.05, 0, 0}}, {"fixed", true}}}},
          {"stages", {{"events", {{{"time", 0}, {"type", "move_wall"}, {"ball", "piston"}, {"velocity", {kV, 0, 0}}}}}}},
          {"integrator", {{"scheme", "velocity_verlet"}}},
          {"time", {{"dt", 1e-6}, {"duration", 0.1}}},
          {"output", {{"probes", {{{"type", "ball"}, {"name", "ball"}, {"balls", {"ball"}}}}}}}};
}

json run(const json& c, const std::string& name) {
  return silodem_test::run_in_scratch(c, "silodem_wall_motion_" + name);
}


}  // namespace

TEST(WallMotion, APistonThrowsABallAtRestAtTwiceItsSpeedAndTheLedgerBooksItsWork) {
  const json s = run(piston_case(), "piston");
  const auto& ball = s["probes"]["ball"];
  const double m = kDensity * 4.0 / 3.0 * M_PI * kR * kR * kR;
  // Contact from t = 0.08 s (0.04 m to close at V) for about pi sqrt(m/k) = 0.25 ms; Omega = 2.5e-3.
  EXPECT_NEAR(ball["final_velocity"][0].get<double>(), 2 * kV, 1e-5 * kV);
  EXPECT_NEAR(ball["final_velocity"][1].get<double>(), 0.0, 1e-12);
  const auto& e = s["energy"];
  EXPECT_NEAR(e["injected"].get<double>(), 0.5 * m * 4 * kV * kV, 1e-4 * m * kV * kV);
  // The trapezoidal work misses where in a step the force starts and ends: at most (1/8) k V² Δt² at
  // the touch and again at the parting (the pair approaches and parts at V), k = 1e5 N/m the pair's.
  EXPECT_LT(std::abs(e["balance"].get<double>()), 0.25 * 1e5 * kV * kV * 1e-12);
  EXPECT_GT(std::abs(e["balance"].get<double>()), 0.0);  // the bound is not idle: the onsets do show
  // The wall went V t: the piston's final position, from the state file.
  std::ifstream in(fs::temp_directory_path() / "silodem_wall_motion_piston" / "state.json");
  const json state = json::parse(in);
  bool found = false;
  for (const auto& b : state["balls"])
    if (b["id"] == "piston") {
      found = true;
      EXPECT_NEAR(b["position"][0].get<double>(), -0.05 + kV * 0.1, 1e-12);
    }
  EXPECT_TRUE(found);
}

TEST(WallMotion, TheEventNamesAWallOrAFixedBall) {
  json both = piston_case();
  both["stages"]["events"][0]["wall"] = "mantle";
  EXPECT_NE(refusal(both).find("not both"), std::string::npos) << refusal(both);
  json mobile = piston_case();
  mobile["stages"]["events"][0]["ball"] = "ball";
  EXPECT_NE(refusal(mobile).find("no fixed ball"), std::string::npos) << refusal(mobile);
  json wall = piston_case();
  wall["stages"]["events"][0].erase("ball");
  wall["stages"]["events"][0]["wall"] = "lid";
  EXPECT_NE(refusal(wall).find("no wall named \"lid\""), std::string::npos) << refusal(wall);
  json fast = piston_case();
  fast["stages"]["events"][0]["velocity"] = {2e6, 0, 0};
  EXPECT_NE(refusal(fast).find("velocity"), std::string::npos) << refusal(fast);
}
