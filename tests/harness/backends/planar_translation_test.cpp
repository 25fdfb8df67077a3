// The planar mode in LAMMPS and LIGGGHTS (planar_frame.hpp): silodem's x-z plane turned onto their
// 2-D x-y plane, and the dump turned back. The runs themselves are compared in test_compare
// (Compare.APlanar*); here, the decks and the refusals.
#include <gtest/gtest.h>

#include <sstream>

#include "deck_helpers.hpp"
#include "harness/backends/planar_frame.hpp"
#include "harness/backends/reference_backend.hpp"
#include "silodem/case/case_loader.hpp"

using namespace harness;
using nlohmann::json;
using deck_helpers::file;
using deck_helpers::has;
using deck_helpers::input_of;

namespace {

// A disc thrown along x and spinning about y above a fixed ball, on a floor vibrating along x, with
// leavers removed below z = -0.05.
json planar_case() {
  return json::parse(R"({
    "name": "planar_deck", "dimension": 2, "grain_inertia": "disc", "gravity": [0, 0, -9.81],
    "contact": {"tangential": "linear_history", "clamp_tensile_force": true},
    "materials": {"g": {"density": 2500, "stiffness": 2e5, "restitution": 0.5, "reference_radius": 0.005,
                        "friction": 0.5, "tangential_damping_ratio": 0.5}},
    "balls": [{"id": "m", "material": "g", "radius": 0.005, "position": [0.01, 0, 0.02], "velocity": [0.3, 0, -0.1],
               "angular_velocity": [0, 7, 0]},
              {"id": "floor_1", "material": "g", "radius": 0.005, "position": [0, 0, 0], "fixed": true}],
    "walls": [],
    "stages": {"outflow": {"below_z": -0.05, "mode": "remove", "every_steps": 20}},
    "integrator": {"scheme": "velocity_verlet", "dashpot_velocity": "half_step"},
    "time": {"dt": 1e-5, "duration": 1e-3}
  })");
}

/// The Atoms and Velocities rows of a data file, by tag: {x y z} and {vx vy vz wx wy wz}.
std::vector<double> row(const std::string& data, const std::string& section, int tag) {
  std::istringstream in(data.substr(data.find(section)));
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::istringstream r(line);
    int t = 0;
    if (!(r >> t) || t != tag) continue;
    std::vector<double> v;
    for (double x; r >> x;) v.push_back(x);
    return v;
  }
  return {};
}

}  // namespace

TEST(PlanarFrame, TheQuarterTurnTakesSilodemsPlaneOntoTheCodesAndBack) {
  const silodem::Mat3 q = planar_turn();
  EXPECT_NEAR(q.determinant(), 1.0, 1e-15);  // a proper rotation: spins turn as positions do
  EXPECT_TRUE((q * silodem::Vec3(1, 2, 3)).isApprox(silodem::Vec3(1, 3, -2)));
  EXPECT_TRUE((q * silodem::Vec3(0, 0, -9.81)).isApprox(silodem::Vec3(0, -9.81, 0)));  // gravity along -y
  EXPECT_TRUE((q * silodem::Vec3(0, 5, 0)).isApprox(silodem::Vec3(0, 0, -5)));          // spin about y: about -z
  EXPECT_TRUE((q.transpose() * q).isIdentity(1e-15));
}

TEST(PlanarFrame, LammpsAndLiggghtsDecksRunInTheirXyPlane) {
  const auto cfg = silodem::load_case(planar_case());
  for (const auto& backend : {make_lammps_backend(), make_liggghts_backend()}) {
    const std::string code = backend->code();
    EXPECT_EQ(backend->not_representable(cfg), "") << code;
    const auto in = input_of(*backend, cfg);
    const std::string deck = file(in, code == "lammps" ? "in.lammps" : "in.liggghts");
    const std::string data = file(in, "data.lmp");
    EXPECT_TRUE(has(deck, "dimension 2\nboundary m m p\n")) << deck;
    EXPECT_LT(deck.find("dimension 2"), deck.find("read_data"));
    EXPECT_TRUE(has(deck, "fix grav mobile gravity 9.8100000000000005 vector 0 -1 0\n")) << deck;
    // enforce2d after the integrator; leavers below silodem's z = -0.05 are below the code's y = -0.05.
    EXPECT_LT(deck.find("fix integrate"), deck.find("fix planar all enforce2d"));
    EXPECT_TRUE(has(deck, "region outflow block INF INF INF -0.050000000000000003 INF INF units box")) << deck;
    EXPECT_TRUE(has(deck, code == "lammps" ? "fix integrate mobile nve/sphere disc\n" : "fix integrate mobile nve/sphere\n"));
    const auto atom = row(data, "Atoms", 1), vel = row(data, "Velocities", 1);
    ASSERT_EQ(atom.size(), 6u) << data;  // type diameter density x y z
    EXPECT_DOUBLE_EQ(atom[3], 0.01);
    EXPECT_DOUBLE_EQ(atom[4], 0.02);  // silodem's height is the code's y
    EXPECT_DOUBLE_EQ(atom[5], 0.0);
    // LIGGGHTS's 2-D mass is pi r^2 rho: the density per area that keeps the sphere's mass.
    EXPECT_DOUBLE_EQ(atom[2], code == "lammps" ? 2500.0 : 2500.0 * 4.0 / 3.0 * 0.005);
    ASSERT_EQ(vel.size(), 6u);
    EXPECT_DOUBLE_EQ(vel[0], 0.3);
    EXPECT_DOUBLE_EQ(vel[1], -0.1);
    EXPECT_DOUBLE_EQ(vel[5], -7.0);  // the spin about silodem's y is about the code's -z
  }
}

TEST(PlanarFrame, AnOscillatingWallMovesAlongItsTurnedAxis) {
  json c = planar_case();
  c["walls"] = json::array({{{"name", "floor"}, {"type", "tray"}, {"material", "g"}, {"radius", {0.005, 0.005}},
                             {"spacing", 0.002}, {"centre", {0, 0, -0.01}}, {"length", 0.1}, {"height", 0.03},
                             {"motion", {{"oscillation", {{"direction", {0, 0, 1}}, {"amplitude", 0.001}, {"frequency", 20}}}}}}});
  c["balls"].erase(1);
  const auto cfg = silodem::load_case(c);
  const std::string deck = file(input_of(*make_lammps_backend(), cfg), "in.lammps");
  // Silodem's z is the code's y: the displacement and velocity variables carry (0, 1, 0).
  EXPECT_TRUE(has(deck, "variable law_floor_ax equal \"v_law_floor_a*(0)\"")) << deck;
  EXPECT_TRUE(has(deck, "variable law_floor_ay equal \"v_law_floor_a*(1)\"")) << deck;
  // A 2-D LAMMPS or LIGGGHTS run refuses any z motion, even a zero one ("cannot define z or vz").
  EXPECT_FALSE(has(deck, "law_floor_az")) << deck;
  EXPECT_TRUE(has(deck, "move variable v_law_floor_ax v_law_floor_ay NULL v_law_floor_vx v_law_floor_vy NULL")) << deck;
}

TEST(PlanarFrame, WhatTheTurnDoesNotCarryIsRefusedWithItsReason) {
  json sphere = planar_case();
  sphere["grain_inertia"] = "sphere";
  const auto cfg = silodem::load_case(sphere);
  EXPECT_EQ(make_lammps_backend()->not_representable(cfg), "");
  EXPECT_TRUE(has(make_liggghts_backend()->not_representable(cfg), "integrates planar grains as discs only"));
  json closing = planar_case();
  closing["stages"] = {{"events", {{{"time", 5e-4}, {"type", "close_outlet"}, {"centre", {0, 0, 0}}, {"diameter", 0.05},
                                    {"thickness", 0.01}}}}};
  const auto closed = silodem::load_case(closing);
  for (const auto& backend : {make_lammps_backend(), make_liggghts_backend()})
    EXPECT_TRUE(has(backend->not_representable(closed), "closure in the planar mode")) << backend->code();
}
