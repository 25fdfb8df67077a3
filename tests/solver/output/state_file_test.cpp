// A run's final state (state.json) reads back exactly, and a continuation from it follows the
// uninterrupted run: what every code's shared start state (compare "from_state_at") relies on.
#include <gtest/gtest.h>

#include <set>

#include <cmath>
#include <filesystem>
#include <map>

#include "silodem/case/case_error.hpp"
#include "silodem/case/case_loader.hpp"
#include "silodem/output/state_file.hpp"
#include "silodem/run/simulation.hpp"

using namespace silodem;
namespace fs = std::filesystem;

namespace {

CaseConfig small_case(double duration) {
  nlohmann::json balls = nlohmann::json::array();
  for (int i = 0; i < 12; ++i)
    balls.push_back({{"id", "b" + std::to_string(i)},
                     {"material", "grain"},
                     {"radius", 0.004 + 0.0001 * (i % 3)},
                     {"position", {0.011 * (i % 3) - 0.011, 0.011 * ((i / 3) % 2), 0.01 + 0.01 * (i / 6)}},
                     {"velocity", {0.0, 0.0, -0.1 * (i % 2)}}});
  const nlohmann::json j = {
      {"format", "silodem-case/1"},
      {"name", "state_test"},
      {"seed", 7},
      {"materials",
       {{"grain", {{"density", 2500.0}, {"stiffness", 1e5}, {"restitution", 0.5}, {"reference_radius", 0.004}}}}},
      {"walls",
       {{{"name", "floor"}, {"type", "disk"}, {"material", "grain"}, {"radius", {0.004, 0.005}}, {"spacing", 0.006},
         {"centre", {0.0, 0.0, 0.0}}, {"diameter", 0.07}}}},
      {"balls", balls},
      {"integrator", {{"scheme", "velocity_verlet"}}},
      {"time", {{"dt_per_contact_time", 0.04}, {"duration", duration}}}};
  return load_case(j);
}

std::map<std::string, Vec3> positions(const StateSnapshot& s) {
  std::map<std::string, Vec3> m;
  for (const auto& b : s.balls) m[b.id] = b.position;
  return m;
}

/// The test's own scratch, cleared the first time it is named: a leftover of another build is
/// not silodem's to keep.
fs::path tmp(const std::string& name) {
  static std::set<std::string> cleared;
  const fs::path d = fs::temp_directory_path() / ("silodem_state_test_" + name);
  if (cleared.insert(name).second) fs::remove_all(d);
  return d;
}

}  // namespace

TEST(StateFile, ContinuationFollowsTheUninterruptedRun) {
  const CaseConfig first = small_case(0.05), whole = small_case(0.06);
  run_case(first, {tmp("first"), false, false});
  const StateSnapshot mid = read_state(tmp("first") / "state.json");
  EXPECT_EQ(mid.balls.size(), first.balls.size());  // the wall balls are part of the state
  EXPECT_NEAR(mid.time, 0.05, first.dt);
  // The state holds the balls as the run left them, in tag order and to the last bit.
  for (std::size_t i = 0; i + 1 < mid.balls.size(); ++i) EXPECT_TRUE(mid.balls[i].id != mid.balls[i + 1].id);

  run_case(continuation(whole, mid), {tmp("rest"), false, false});
  run_case(whole, {tmp("whole"), false, false});
  const auto a = positions(read_state(tmp("rest") / "state.json"));
  const auto b = positions(read_state(tmp("whole") / "state.json"));
  ASSERT_EQ(a.size(), b.size());
  // Not bitwise: at the restart the forces are evaluated afresh from (x, v), where the running
  // integrator had them from its predicted velocity; the difference stays at rounding level here.
  double worst = 0.0;
  for (const auto& [id, x] : a) worst = std::max(worst, (x - b.at(id)).norm());
  EXPECT_LT(worst, 1e-9) << "m after " << (0.06 - 0.05) / whole.dt << " steps";
}

TEST(StateFile, ContinuationRefusesAnotherTimeStepOrALaterStart) {
  const CaseConfig first = small_case(0.02);
  run_case(first, {tmp("refuse"), false, false});
  StateSnapshot s = read_state(tmp("refuse") / "state.json");
  CaseConfig other = small_case(0.05);
  other.dt *= 0.5;
  EXPECT_THROW(continuation(other, s), CaseError);
  EXPECT_THROW(continuation(small_case(0.01), s), CaseError);
}
