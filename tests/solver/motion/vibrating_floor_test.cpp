// A grain on a floor of wall balls vibrating vertically, z_f = A (1 − cos ωt) (the motion law with
// φ = −π/2: the floor starts at rest, at its lowest point). A rigid grain on it leaves the floor
// when the floor's acceleration A ω² cos ωt falls to −g, at ωt = arccos(−1/Γ), Γ = A ω²/g; below
// Γ = 1 it never leaves. On a contact spring the grain is a base-excited oscillator: its contact
// force lags the rigid one by about 2ζ (ω/ω_n)³ rad (3e-6 here), far below the one step (ω Δt) in
// which the force's sign change is seen.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "silodem/case/case_loader.hpp"
#include "silodem/output/state_file.hpp"
#include "silodem/run/simulation.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr double kA = 0.01, kG = 9.81, kDt = 1e-5, kStart = 0.5;

json floor_case(double gamma) {
  const double f = std::sqrt(gamma * kG / kA) / (2.0 * M_PI);
  json motion = {{"start_time", kStart},
                 {"oscillation", {{"direction", {0, 0, 1}}, {"amplitude", kA}, {"frequency", f}, {"phase", -M_PI / 2}}}};
  return {{"name", "vibrating_floor"},
          {"gravity", {0, 0, -kG}},
          {"materials",
           {{"grain", {{"density", 2500.0}, {"stiffness", 1e6}, {"restitution", 0.05}, {"reference_radius", 0.02}}},
            {"wall", {{"density", 7800.0}, {"stiffness", 1e6}, {"damping", 50.0}}}}},
          {"walls",
           {{{"name", "floor"}, {"type", "disk"}, {"material", "wall"}, {"radius", {0.005, 0.005}}, {"spacing", 0.006},
             {"centre", {0, 0, 0}}, {"diameter", 0.06}, {"motion", motion}}}},
          // Straight above the centre ball of the floor: it settles there, at rest, before the floor moves.
          {"balls", {{{"id", "grain"}, {"material", "grain"}, {"radius", 0.02}, {"position", {0, 0, 0.0245}}}}},
          {"integrator", {{"scheme", "velocity_verlet"}}},
          {"time", {{"dt", kDt}, {"duration", kStart + 0.5 / f}}},
          {"output", {{"series_interval", kDt}}}};
}

struct Row {
  double t, wall_fz, drift;
};

std::vector<Row> run(const json& c, const std::string& name) {
  const fs::path out = fs::temp_directory_path() / ("silodem_vibrating_floor_" + name);
  fs::remove_all(out);  // the test's own scratch
  silodem::run_case(silodem::load_case(c), {out, false, false});
  std::ifstream in(out / "series.csv");
  std::string line;
  std::getline(in, line);
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    std::vector<double> v;
    std::stringstream s(line);
    for (std::string cell; std::getline(s, cell, ',');) v.push_back(std::stod(cell));
    rows.push_back({v[0], v[14], v[8]});  // t, wall_fz, rel_drift
  }
  return rows;
}

}  // namespace

TEST(VibratingFloor, AGrainLeavesAFloorAboveOneGAtThePhaseOfTheRigidClosedForm) {
  const double gamma = 2.0, omega = std::sqrt(gamma * kG / kA);
  const auto rows = run(floor_case(gamma), "above");
  double t_off = -1.0;
  for (const Row& r : rows)
    if (r.t > kStart && r.wall_fz >= 0.0) {  // the floor no longer carries the grain
      t_off = r.t;
      break;
    }
  ASSERT_GT(t_off, kStart);
  const double phase = omega * (t_off - kStart);
  EXPECT_NEAR(phase, std::acos(-1.0 / gamma), 2.0 * omega * kDt) << "take-off at " << phase * 180 / M_PI << " deg";
  // The wall's work is in the ledger: the balance closes to the piston test's order.
  EXPECT_LT(std::abs(rows.back().drift), 1e-3);
}

TEST(VibratingFloor, BelowOneGTheGrainStaysOnTheFloor) {
  const double gamma = 0.8;
  const auto rows = run(floor_case(gamma), "below");
  const double m = 2500.0 * 4.0 / 3.0 * M_PI * std::pow(0.02, 3);
  double least = INFINITY;  // the least downward force on the floor while it moves
  for (const Row& r : rows)
    if (r.t > kStart) least = std::min(least, -r.wall_fz);
  // At the floor's highest point the grain weighs m g (1 − Γ).
  EXPECT_NEAR(least, m * kG * (1.0 - gamma), 0.01 * m * kG);
}

// A continuation from a state starts its walls where the law has them (their places at the law's
// origin are the case's, not the state's), so it follows the uninterrupted run: the floor to the
// last bits of its closed form, the grain to rounding (forces evaluated afresh at the restart).
TEST(VibratingFloor, AContinuationKeepsTheFloorOnItsLaw) {
  json early = floor_case(2.0), whole = floor_case(2.0);
  early["time"]["duration"] = kStart + 0.02;
  whole["time"]["duration"] = kStart + 0.04;
  const fs::path dir = fs::temp_directory_path() / "silodem_vibrating_floor_continued";
  fs::remove_all(dir);  // the test's own scratch
  silodem::run_case(silodem::load_case(early), {dir / "early", false, false});
  const silodem::CaseConfig all = silodem::load_case(whole);
  silodem::run_case(silodem::continuation(all, silodem::read_state(dir / "early" / "state.json")), {dir / "rest", false, false});
  silodem::run_case(all, {dir / "whole", false, false});
  std::map<std::string, silodem::Vec3> rest, ref;
  for (const auto& b : silodem::read_state(dir / "rest" / "state.json").balls) rest[b.id] = b.position;
  for (const auto& b : silodem::read_state(dir / "whole" / "state.json").balls) ref[b.id] = b.position;
  ASSERT_EQ(rest.size(), ref.size());
  for (const auto& [id, x] : rest) EXPECT_LT((x - ref.at(id)).norm(), id == "grain" ? 1e-9 : 1e-15) << id;
}
