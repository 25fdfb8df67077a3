// A frictional grain with rolling resistance in a drum of wall balls turning about a horizontal
// axis (gravity along −y, the drum's axis along z). Whatever the grain does against the bumpy
// wall, its angular momentum about the axis changes only by the torques on it, so over a window
//   ∫ T_wall dt = ∫ τ_gravity dt − ΔL = −m g ∫ x_b dt − ΔL,
// T_wall being the torque the grain puts on the drum (the wall_load probe: forces' moments and the
// contact torques), x_b the grain's distance from the axis across gravity, L its angular momentum
// about the axis, m (x × v)_z + I ω_z. The sampled sums differ from the integrals by the
// trapezoid's end terms, at most Δt max|T|. The drum's power on the grain is −Ω·T exactly
// (rigid-body velocities), and the ledger, which books that work, closes.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "silodem/case/case_loader.hpp"
#include "silodem/run/simulation.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr double kOmega = 1.0, kR = 0.01, kRho = 2500.0, kG = 9.81, kFrom = 1.0, kEnd = 2.0;

json drum_case() {
  const json spin = {{"rotation", {{"centre", {0, 0, 0}}, {"axis", {0, 0, 1}}, {"angular_speed", kOmega}}}};
  const json frictional = {{"friction", 0.5}, {"tangential_damping_ratio", 0.5}, {"rolling_friction", 0.1},
                           {"rolling_damping_ratio", 0.3}};
  json grain = {{"density", kRho}, {"stiffness", 1e5}, {"restitution", 0.3}, {"reference_radius", kR}};
  json wall = {{"density", 7800.0}, {"stiffness", 1e5}, {"damping", 4.0}};
  grain.update(frictional);
  wall.update(frictional);
  json cap = wall;
  cap["friction"] = 0.0;
  cap["rolling_friction"] = 0.0;
  const auto disk = [&](const std::string& name, double z) {
    return json{{"name", name}, {"type", "disk"}, {"material", "cap"}, {"radius", {0.005, 0.005}}, {"spacing", 0.006},
                {"centre", {0, 0, z}}, {"diameter", 0.2}, {"motion", spin}};
  };
  return {{"name", "rotating_drum"},
          {"gravity", {0, -kG, 0}},
          {"contact", {{"tangential", "linear_history"}, {"rolling", "epsd"}}},
          {"materials", {{"grain", grain}, {"wall", wall}, {"cap", cap}}},
          {"walls",
           {{{"name", "drum"}, {"type", "cylinder"}, {"material", "wall"}, {"radius", {0.005, 0.005}}, {"spacing", 0.006},
             {"centre", {0, 0, -0.005}}, {"diameter", 0.2}, {"height", 0.04}, {"motion", spin}},
            disk("cap_lo", 0.003), disk("cap_hi", 0.037)}},  // end plates 2 mm clear of the grain
          {"balls", {{{"id", "g"}, {"material", "grain"}, {"radius", kR}, {"position", {0, -0.08, 0.015}}}}},
          {"integrator", {{"scheme", "velocity_verlet"}}},
          {"time", {{"dt_per_contact_time", 0.02}, {"duration", kEnd}}},
          {"output",
           {{"probes",
             {{{"type", "ball"}, {"name", "g"}, {"balls", {"g"}}, {"from_time", kFrom}},
              {{"type", "wall_load"}, {"name", "drum"}, {"wall", "drum"}, {"from_time", kFrom}, {"interval", 1e-6}},
              {{"type", "wall_load"}, {"name", "cap_lo"}, {"wall", "cap_lo"}, {"from_time", kFrom}},
              {{"type", "wall_load"}, {"name", "cap_hi"}, {"wall", "cap_hi"}, {"from_time", kFrom}},
              {{"type", "wall_pressure"}, {"name", "drum_map"}, {"wall", "drum"}, {"angle_bins", 36}, {"height_bins", 1}}}}}}};
}

double z_of_cross(const json& a, const json& b) {
  return a[0].get<double>() * b[1].get<double>() - a[1].get<double>() * b[0].get<double>();
}

}  // namespace

TEST(RotatingDrum, TheWallTorqueBalancesGravityAndTheGrainsAngularMomentum) {
  const fs::path out = fs::temp_directory_path() / "silodem_rotating_drum";
  fs::remove_all(out);  // the test's own scratch
  const silodem::CaseConfig cfg = silodem::load_case(drum_case());
  const json s = silodem::run_case(cfg, {out, false, false});
  const json& probes = s["probes"];
  const json& g = probes["g"];
  const json& w = g["window"];
  const double m = kRho * 4.0 / 3.0 * M_PI * kR * kR * kR, inertia = 0.4 * m * kR * kR;
  const auto momentum = [&](const json& x, const json& v, const json& om) {
    return m * z_of_cross(x, v) + inertia * om[2].get<double>();
  };
  const double d_l = momentum(g["final_position"], g["final_velocity"], g["final_angular_velocity"]) -
                     momentum(w["start_position"], w["start_velocity"], w["start_angular_velocity"]);
  const double span = kEnd - w["start_time"].get<double>();
  double torque = 0.0;
  for (const char* wall : {"drum", "cap_lo", "cap_hi"}) torque += probes[wall]["torque_mean"][2].get<double>();
  const double gravity_term = -m * kG * w["mean_position"][0].get<double>();
  // The largest torque on the drum along the window, for the bound of the sums' end terms.
  double largest = 0.0;
  std::ifstream rows(out / "probes" / "drum.csv");
  std::string line;
  std::getline(rows, line);
  while (std::getline(rows, line)) {
    std::vector<double> v;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) v.push_back(std::stod(cell));
    if (v[0] >= kFrom) largest = std::max(largest, std::abs(v[6]));
  }
  ASSERT_GT(largest, 0.0);
  EXPECT_LT(torque, -0.1 * m * kG * 0.08) << "the grain rides up the rising side and loads the drum against its turn";
  EXPECT_NEAR(torque * span, gravity_term * span - d_l, cfg.dt * largest);
  // The drum's power on the grain, −Ω T_z, and the ledger that books it.
  EXPECT_NEAR(probes["drum"]["power_mean"].get<double>(), -kOmega * probes["drum"]["torque_mean"][2].get<double>(),
              1e-9 * std::abs(torque));
  EXPECT_GT(s["energy"]["injected"].get<double>(), 0.0);
  EXPECT_LT(std::abs(s["energy"]["relative_drift"].get<double>()), 1e-3);
}

// The pressure map of a turning wall is drawn in the wall's own frame: at the end the grain's load
// is in the cell at the drum angle under it, its lab angle less the turn Ω t (36 cells of 10°).
TEST(RotatingDrum, TheWallPressureMapTurnsWithTheDrum) {
  const fs::path out = fs::temp_directory_path() / "silodem_rotating_drum_map";
  fs::remove_all(out);  // the test's own scratch
  const json s = silodem::run_case(silodem::load_case(drum_case()), {out, false, false});
  const json& x = s["probes"]["g"]["final_position"];
  const double lab = std::atan2(x[1].get<double>(), x[0].get<double>());
  const double own = std::fmod(std::fmod(lab - kOmega * kEnd, 2 * M_PI) + 2 * M_PI, 2 * M_PI);
  std::ifstream in(out / "probes" / "drum_map.csv");
  std::string line;
  std::getline(in, line);
  int loaded = -1;
  double most = 0.0;
  while (std::getline(in, line)) {
    std::vector<double> v;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) v.push_back(std::stod(cell));
    if (v[9] > most) most = v[9], loaded = int(v[0]);  // pressure_final
  }
  ASSERT_GE(loaded, 0);
  EXPECT_EQ(loaded, int(own / (2 * M_PI / 36))) << "grain at drum angle " << own * 180 / M_PI << " deg";
}

