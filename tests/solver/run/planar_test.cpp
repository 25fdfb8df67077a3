// The planar mode ("dimension": 2, docs/model.md §13): grains in the x–z plane spinning about y,
// with the inertia of a disc (1/2 m r²) or of a sphere (2/5). Closed forms: slip to roll ends at
// u0/(1 + κ), rolling down an incline accelerates at g sin θ/(1 + κ). A grain striking a wall ball
// off the plane stays in it, bit for bit, where the same run in 3-D is pushed out. The loader refuses
// whatever would leave the plane, naming it.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "../case_runs.hpp"
#include "references/friction.hpp"
#include "silodem/case/case_error.hpp"
#include "silodem/case/case_loader.hpp"
#include "silodem/run/simulation.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

using silodem_test::refusal;

namespace {

constexpr double kR = 0.005, kFloorRadius = 1000.0, kG = 9.81, kDensity = 2500.0;
const double kMass = kDensity * 4.0 / 3.0 * M_PI * kR * kR * kR;

json grain(double mu) {
  // Per-ball k 2e5 N/m (pair 1e5 with the floor); a tangential dashpot calms the stick's ringing.
  return {{"density", kDensity}, {"stiffness", 2e5}, {"restitution", 0.5}, {"reference_radius", kR},
          {"friction", mu},      {"tangential_damping_ratio", 0.5}};
}

/// A grain on a floor ball of radius 1000 m, at its static overlap, thrown at u0 along x, under
/// gravity tilted by θ about y (an incline, down-slope along +x).
json on_floor(const std::string& name, const std::string& inertia, double mu, double u0, double theta, double duration) {
  const double k_pair = 1e5, gz = kG * std::cos(theta);
  return {{"name", name},
          {"dimension", 2},
          {"grain_inertia", inertia},
          {"gravity", {kG * std::sin(theta), 0.0, -gz}},
          {"contact", {{"tangential", "linear_history"}}},
          {"materials", {{"grain", grain(mu)}}},
          {"balls",
           {{{"id", "ball"}, {"material", "grain"}, {"radius", kR},
             {"position", {0.0, 0.0, kFloorRadius + kR - kMass * gz / k_pair}}, {"velocity", {u0, 0.0, 0.0}}},
            {{"id", "floor"}, {"material", "grain"}, {"radius", kFloorRadius}, {"position", {0, 0, 0}}, {"fixed", true}}}},
          {"time", {{"dt", 1e-5}, {"duration", duration}}},
          {"output", {{"probes", {{{"type", "ball"}, {"name", "ball"}, {"balls", {"ball"}}}}}}}};
}

json run(const json& c) {
  return silodem_test::run_in_scratch(c, "silodem_planar_" + c["name"].get<std::string>());
}

json final_velocity(const json& s) { return s["probes"]["ball"]["final_velocity"]; }
json final_spin(const json& s) { return s["probes"]["ball"]["final_angular_velocity"]; }


}  // namespace

TEST(PlanarMode, ADiscSlidesThenRollsAtTwoThirdsOfTheSpeedAndASphereAtFiveSevenths) {
  // Tolerance as in FrictionOracles.SlipToRoll…: the floor's tilt x/1000 m moves v by ≤ 2e-4 m/s.
  for (const auto& [inertia, kappa] : {std::pair{"disc", 0.5}, std::pair{"sphere", 0.4}}) {
    const double u0 = 1.0, mu = 0.5;
    const auto oracle = references::slip_to_roll(u0, mu, kG, kR, kappa);
    const double t1 = std::round(0.5 * oracle.slip_time / 1e-5) * 1e-5;
    const json slide = run(on_floor(std::string("slide_") + inertia, inertia, mu, u0, 0.0, t1));
    EXPECT_NEAR(final_velocity(slide)[0].get<double>(), oracle.speed(t1), 2e-4) << inertia;
    EXPECT_NEAR(final_spin(slide)[1].get<double>(), oracle.spin(t1), 2e-4 / kR) << inertia;
    const json roll = run(on_floor(std::string("roll_") + inertia, inertia, mu, u0, 0.0,
                                   std::round(1.5 * oracle.slip_time / 1e-5) * 1e-5));
    EXPECT_NEAR(final_velocity(roll)[0].get<double>(), u0 / (1.0 + kappa), 2e-4) << inertia;
    EXPECT_NEAR(final_velocity(roll)[0].get<double>(), final_spin(roll)[1].get<double>() * kR, 2e-4) << inertia;
  }
}

TEST(PlanarMode, ADiscRollsDownAnInclineAtTwoThirdsOfGSinTheta) {
  // Rolling without slip needs tan θ ≤ μ (1 + κ)/κ = 3 μ: θ = 10°, μ = 0.5. After 0.1 s, v = a t to
  // the tangential spring's start-up swing (F/k_t ω_t ≈ 1e-4 m/s, damped) and the floor's tilt.
  const double theta = 10.0 * M_PI / 180.0, t = 0.1;
  const json s = run(on_floor("incline", "disc", 0.5, 0.0, theta, t));
  EXPECT_NEAR(final_velocity(s)[0].get<double>(), 2.0 / 3.0 * kG * std::sin(theta) * t, 3e-4);
  EXPECT_NEAR(final_velocity(s)[0].get<double>(), final_spin(s)[1].get<double>() * kR, 3e-4);
}

TEST(PlanarMode, AGrainStrikingAWallBallOffThePlaneStaysInIt) {
  // A grain falls onto a fixed ball set 0.3 r off the plane: in 3-D it leaves along y; planar, its
  // force's y part is dropped and it stays at y = 0 with no spin about x or z, exactly.
  json c = on_floor("off_plane", "disc", 0.5, 0.0, 0.0, 0.05);
  c["balls"] = {{{"id", "ball"}, {"material", "grain"}, {"radius", kR}, {"position", {0.001, 0.0, 0.02}}},
                {{"id", "post"}, {"material", "grain"}, {"radius", kR}, {"position", {0.0, 0.3 * kR, 0.0}}, {"fixed", true}}};
  const json planar = run(c);
  EXPECT_EQ(final_velocity(planar)[1].get<double>(), 0.0);
  EXPECT_EQ(final_spin(planar)[0].get<double>(), 0.0);
  EXPECT_EQ(final_spin(planar)[2].get<double>(), 0.0);
  EXPECT_GT(std::abs(final_velocity(planar)[0].get<double>()), 0.01);  // it was struck, and moved in the plane
  c["name"] = "off_plane_3d";
  c["dimension"] = 3;
  c.erase("grain_inertia");
  EXPECT_LT(final_velocity(run(c))[1].get<double>(), -0.01);  // the same fall in 3-D: pushed to −y
}

TEST(PlanarMode, TheLoaderRefusesWhatLeavesThePlane) {
  const json base = on_floor("refuse", "disc", 0.5, 0.0, 0.0, 0.01);
  EXPECT_EQ(refusal(base), "");
  json c = base;
  c["balls"][0]["position"][1] = 1e-3;
  EXPECT_NE(refusal(c).find("ball \"ball\" is at y = 0.001 m"), std::string::npos) << refusal(c);
  c = base;
  c["balls"][0]["angular_velocity"] = {1.0, 0.0, 0.0};
  EXPECT_NE(refusal(c).find("spins about x or z"), std::string::npos) << refusal(c);
  c = base;
  c["gravity"] = {0.0, 1.0, -9.81};
  EXPECT_NE(refusal(c).find("$.gravity"), std::string::npos) << refusal(c);
  c = base;
  c["dimension"] = 3;
  EXPECT_NE(refusal(c).find("grain_inertia"), std::string::npos) << refusal(c);
  c = base;
  c["surfaces"] = {{{"name", "drum"}, {"material", "grain"},
                    {"axis", {{"point", {0, 0, 0}}, {"direction", {1, 0, 0}}}}, {"profile", {{0.1, -0.1}, {0.1, 0.1}}},
                    {"angular_speed", 1.0}}};
  EXPECT_NE(refusal(c).find("spins about an axis in the plane"), std::string::npos) << refusal(c);
  c["surfaces"][0]["axis"]["direction"] = {1, 1, 0};
  EXPECT_NE(refusal(c).find("neither in the plane nor along y"), std::string::npos) << refusal(c);
  c["surfaces"][0]["axis"]["direction"] = {0, 1, 0};  // a drum about y: its section is a circle in the plane
  EXPECT_EQ(refusal(c), "");
  c = base;
  c["walls"] = {{{"name", "silo"}, {"type", "cylinder"}, {"material", "grain"}, {"radius", {0.004, 0.004}},
                 {"spacing", 0.006}, {"centre", {0, 0, 0}}, {"diameter", 0.1}, {"height", 0.1}}};
  EXPECT_NE(refusal(c).find("not a planar wall"), std::string::npos) << refusal(c);
}

TEST(PlanarMode, DiscsDischargeThroughATraySlotAndTheRestCarryTheirWeight) {
  // 40 discs (d = 8 mm) in a planar tray 12 cm long with a slot of 3 d at its middle (seed 001's
  // slot width): the run goes on until every disc has either left through the slot or rests on
  // the floor beside it (the equilibrium test, from 1.5 s), all of them in the plane. Oracles: the
  // count (exits + remaining = 40), y = 0 exactly, the floor's vertical load against the remaining
  // weight (1 %: at rest the unbalanced force is below p_ft = 0.5 % of the weight; the piles beside
  // a slot go on shedding discs for seconds, so a fixed end time met them in motion), and the
  // energy ledger (drift 9e-4 measured, gate 5e-3).
  json balls = json::array();
  for (int row = 0; row < 5; ++row)
    for (int col = 0; col < 8; ++col)
      balls.push_back({{"id", "g" + std::to_string(8 * row + col)}, {"material", "grain"}, {"radius", 0.004},
                       {"position", {-0.05 + 0.0125 * col + (row % 2 ? 0.006 : 0.0), 0.0, 0.01 + 0.0125 * row}}});
  const json c = {
      {"name", "tray_discharge"},
      {"dimension", 2},
      {"grain_inertia", "disc"},
      {"contact", {{"tangential", "linear_history"}}},
      {"materials", {{"grain", {{"density", 2500}, {"stiffness", 2e4}, {"restitution", 0.5}, {"reference_radius", 0.004},
                                {"friction", 0.5}, {"tangential_damping_ratio", 0.5}}}}},
      {"balls", balls},
      {"walls", {{{"name", "tray"}, {"type", "tray"}, {"material", "grain"}, {"radius", {0.004, 0.004}}, {"spacing", 0.002},
                  {"centre", {0, 0, 0}}, {"length", 0.12}, {"height", 0.08}, {"slots", {{{"x", 0.0}, {"width", 0.024}}}}}}},
      {"stages", {{"outflow", {{"below_z", -0.03}, {"mode", "remove"}}}}},
      {"time", {{"dt_per_contact_time", 0.02}, {"duration", 8.0}}},
      {"equilibrium", {{"check_interval_steps", 100}, {"min_time", 1.5}, {"p_ft", 0.005}}},
      {"output", {{"series_interval", 0.01},
                  {"probes", {{{"type", "outflow"}, {"name", "out"}}, {{"type", "wall_load"}, {"name", "tray"}, {"wall", "tray"}}}}}}};
  const json s = run(c);
  ASSERT_EQ(s["run"]["stop_reason"], "equilibrium") << "the discs did not come to rest in 8 s";
  const long remaining = s["balls"]["mobile"].get<long>(), exits = s["probes"]["out"]["exits"].get<long>();
  EXPECT_EQ(exits + remaining, 40);
  EXPECT_GT(exits, 0);
  EXPECT_GT(remaining, 0);
  const double weight = double(remaining) * kMass * 0.8 * 0.8 * 0.8 * kG;  // r = 4 mm against kMass's 5 mm
  EXPECT_NEAR(-s["probes"]["tray"]["force_final"][2].get<double>(), weight, 0.01 * weight);
  EXPECT_EQ(s["probes"]["tray"]["force_final"][1].get<double>(), 0.0);
  EXPECT_LT(s["energy"]["max_abs_relative_drift"].get<double>(), 5e-3);
  std::ifstream state(fs::temp_directory_path() / "silodem_planar_tray_discharge" / "state.json");
  const json final_state = json::parse(state);
  long in_plane = 0;
  for (const auto& b : final_state["balls"])
    if (b["id"].get<std::string>()[0] == 'g')  // the discs (the tray's balls are "tray_<n>")
      in_plane += b["position"][1].get<double>() == 0.0 && b["angular_velocity"][0].get<double>() == 0.0 &&
                  b["angular_velocity"][2].get<double>() == 0.0;
  EXPECT_EQ(in_plane, remaining);
}
