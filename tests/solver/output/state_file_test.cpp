// A run's final state (state.json) reads back exactly, and a continuation from it follows the
// uninterrupted run: what every code's shared start state (compare "from_state_at") relies on.
#include <gtest/gtest.h>

#include <set>

#include <cmath>
#include <filesystem>
#include <fstream>
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

namespace {

/// A spinning ball far from everything and a ball thrown without spin along a floor (a fixed ball
/// of radius 1000 m, as in cases/slip_to_roll.json), run past the slip-to-roll time t_s.
nlohmann::json spin_case(bool rotating) {
  const double r = 0.005, static_overlap = 2500 * 4.0 / 3.0 * M_PI * r * r * r * 9.81 / 1e5;  // m g / k_pair
  nlohmann::json grain = {{"density", 2500.0}, {"stiffness", 2e5}, {"restitution", 0.5}, {"reference_radius", r}};
  nlohmann::json spinner = {{"id", "spinner"}, {"material", "grain"}, {"radius", r}, {"position", {0.0, 0.5, 1000.5}},
                            {"velocity", {0.1, 0.0, 0.0}}};
  nlohmann::json j = {
      {"name", "spin_state"},
      {"materials", {{"grain", grain}}},
      {"balls",
       {spinner,
        {{"id", "ball"}, {"material", "grain"}, {"radius", r}, {"position", {0.0, 0.0, 1000.0 + r - static_overlap}},
         {"velocity", {1.0, 0.0, 0.0}}},
        {{"id", "floor"}, {"material", "grain"}, {"radius", 1000.0}, {"position", {0.0, 0.0, 0.0}}, {"fixed", true}}}},
      {"integrator", {{"scheme", "velocity_verlet"}}},
      // t_s = 2 u0/(7 μ g) = 0.0583 s at μ = 0.5: rolling from then on.
      {"time", {{"dt", 1e-5}, {"duration", 0.09}}},
      {"output", {{"probes", {{{"type", "ball"}, {"name", "ball"}, {"balls", {"ball"}}}}}}}};
  if (rotating) {
    j["contact"] = {{"tangential", "linear_history"}};
    j["materials"]["grain"]["friction"] = 0.5;
    j["materials"]["grain"]["tangential_damping_ratio"] = 0.5;
    j["balls"][0]["angular_velocity"] = {3.0, -7.0, 11.0};
  }
  return j;
}

}  // namespace

TEST(StateFile, ARotatingRunKeepsEachBallsAngularVelocity) {
  const fs::path dir = tmp("spin");
  run_case(load_case(spin_case(true)), {dir, false, false});
  std::ifstream in(dir / "state.json");
  const nlohmann::json state = nlohmann::json::parse(in);
  std::map<std::string, nlohmann::json> ball;
  for (const auto& b : state["balls"]) ball[b["id"]] = b;
  // No contact, no torque: the spin a ball was given is kept to the last bit.
  EXPECT_EQ(ball["spinner"]["angular_velocity"], nlohmann::json({3.0, -7.0, 11.0}));
  // The thrown ball rolls: ω = v/r = 5 u0/(7 r) about +y (docs/theory.md §10.4), within 1e-3 as in
  // cases/slip_to_roll.json (the floor's tilt x/1000 m changes the speed by ≤ 6e-4 of it).
  const nlohmann::json w = ball["ball"]["angular_velocity"];
  const double rolling = 5.0 * 1.0 / (7.0 * 0.005);
  EXPECT_NEAR(w[1].get<double>(), rolling, 1e-3 * rolling);
  EXPECT_LE(std::abs(w[0].get<double>()) + std::abs(w[2].get<double>()), 1e-12 * rolling);
  // The same ω as the ball probe's last sample, bit for bit, and read back as written.
  std::ifstream sin(dir / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(sin);
  EXPECT_EQ(summary["probes"]["ball"]["final_angular_velocity"], w);
  const StateSnapshot s = read_state(dir / "state.json");
  for (const auto& b : s.balls) {
    if (b.id != "ball") continue;
    EXPECT_EQ(b.angular_velocity, Vec3(w[0].get<double>(), w[1].get<double>(), w[2].get<double>()));
  }
  EXPECT_FALSE(ball["floor"].contains("angular_velocity"));  // a wall ball does not spin
}

TEST(StateFile, AFrictionlessRunWritesNoAngularVelocity) {
  const fs::path dir = tmp("no_spin");
  run_case(load_case(spin_case(false)), {dir, false, false});
  std::ifstream in(dir / "state.json");
  const nlohmann::json state = nlohmann::json::parse(in);
  ASSERT_EQ(state["balls"].size(), 3u);
  for (const auto& b : state["balls"]) EXPECT_FALSE(b.contains("angular_velocity")) << b["id"];
  // Without friction nothing slows the thrown ball: its 1 m/s is kept but for the floor's tilt,
  // x/1000 m, which changes it by at most g (x/R) t = 8e-5 m/s here.
  for (const auto& b : state["balls"]) {
    if (b["id"] != "ball") continue;
    EXPECT_NEAR(b["velocity"][0].get<double>(), 1.0, 1e-4);
  }
}
