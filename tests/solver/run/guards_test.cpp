// Run guards (run/guards.hpp): a run that goes wrong stops with a RunError naming the ball or
// pair, the step and the likely cause, leaves its last state in DIR.failed (never DIR), and a
// run within its limits is not disturbed.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "silodem/case/case_loader.hpp"
#include "silodem/run/simulation.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json two_balls(double speed, double duration, const json& guards = json::object()) {
  json c = {{"name", "guards"},
            {"seed", 1},
            {"gravity", {0.0, 0.0, 0.0}},
            {"materials", {{"g", {{"density", 2500}, {"stiffness", 1e5}, {"damping", 0.0}}}}},
            {"balls",
             {{{"id", "left"}, {"material", "g"}, {"radius", 0.005}, {"position", {-0.006, 0.0, 0.0}}, {"velocity", {speed, 0.0, 0.0}}},
              {{"id", "right"}, {"material", "g"}, {"radius", 0.005}, {"position", {0.006, 0.0, 0.0}}, {"velocity", {-speed, 0.0, 0.0}}}}},
            {"integrator", {{"scheme", "velocity_verlet"}}},
            {"time", {{"dt", 1e-6}, {"duration", duration}}}};
  if (!guards.empty()) c["guards"] = guards;
  return c;
}

std::string run_error(const json& c, const fs::path& out) {
  fs::remove_all(out);
  fs::remove_all(out.string() + ".failed");
  try {
    silodem::run_case(silodem::load_case(c), {out, false, false});
  } catch (const silodem::RunError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(RunGuards, AnImpactTooFastForTheStiffnessStopsAtTheOverlapGuard) {
  // Closing at 40 m/s, pair k = 5e4 N/m, m_eff = 6.5e-4 kg: the overlap would reach 0.9 r.
  const fs::path out = fs::temp_directory_path() / "silodem_guard_overlap";
  const std::string what = run_error(two_balls(20.0, 1e-3), out);
  EXPECT_NE(what.find("overlaps"), std::string::npos) << what;
  EXPECT_NE(what.find("\"right\""), std::string::npos) << what;
  EXPECT_NE(what.find("contact time"), std::string::npos) << what;
  EXPECT_FALSE(fs::exists(out));                                  // nothing that looks complete
  EXPECT_TRUE(fs::exists(out.string() + ".failed/state.json"));  // the last state, for inspection
  const json s = json::parse(std::ifstream(out.string() + ".failed/summary.json"));
  EXPECT_EQ(s["status"], "failed");
}

TEST(RunGuards, ABallLeavingTheDomainStopsTheRun) {
  json c = two_balls(0.0, 0.2, {{"domain_margin", 0.1}});
  c["balls"][0]["velocity"] = {0.0, 0.0, 5.0};  // 1 m in the run: past the 0.1 m margin
  const std::string what = run_error(c, fs::temp_directory_path() / "silodem_guard_domain");
  EXPECT_NE(what.find("\"left\""), std::string::npos) << what;
  EXPECT_NE(what.find("left the domain"), std::string::npos) << what;
}

TEST(RunGuards, StepLimitStopsARunAndAGentleRunPasses) {
  const std::string what = run_error(two_balls(0.1, 1e-3, {{"max_steps", 100}}), fs::temp_directory_path() / "silodem_guard_steps");
  EXPECT_NE(what.find("max_steps"), std::string::npos) << what;
  EXPECT_NE(what.find("step 100"), std::string::npos) << what;
  // The same collision at 0.1 m/s, no limit: no guard trips.
  EXPECT_EQ(run_error(two_balls(0.1, 1e-3), fs::temp_directory_path() / "silodem_guard_ok"), "");
}
