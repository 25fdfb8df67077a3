// The velocity field probe against grains in free flight (no gravity, no contact): each cell's
// mean velocity is that of the grains crossing it, the radial part taken along the ring's radius,
// and its solid fraction their volume over the ring's; grains off the grid and fixed balls are
// not counted; sampling stops at to_time.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "silodem/case/case_loader.hpp"
#include "silodem/run/simulation.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr double kR = 0.001;  // grain radius, m

json grain(const std::string& id, double x, double y, double z, double vx, double vy, double vz, bool fixed = false) {
  json b = {{"id", id}, {"material", "grain"}, {"radius", kR}, {"position", {x, y, z}}, {"velocity", {vx, vy, vz}}};
  if (fixed) b["fixed"] = true, b.erase("velocity");
  return b;
}

/// Rings of 1 cm about the axis through (0.1, 0, 0), two bands of 5 cm from z = 0.
json flight_case() {
  const double c = 0.1;
  json balls = json::array({
      grain("a", c + 0.005, 0.0, 0.02, 0.0, 0.0, -0.1),        // ring 0, band 0
      grain("b", c, 0.015, 0.02, 0.0, 0.2, -0.3),              // ring 1, band 0: radially outward at 0.2
      grain("c", c - 0.015, 0.0, 0.02, 0.2, 0.0, -0.5),        // ring 1, band 0: radially inward at 0.2
      grain("d", c + 0.005, 0.0, 0.07, 0.0, 0.0, 0.4),         // ring 0, band 1
      grain("off", c + 0.05, 0.0, 0.02, 0.0, 0.0, -1.0),       // beyond the radius
      grain("wall", c + 0.005, 0.0, 0.03, 0.0, 0.0, 0.0, true)  // fixed
  });
  json probe = {{"type", "velocity_field"}, {"name", "field"}, {"centre", {c, 0.0, 0.0}}, {"radius", 0.02},
                {"z", {0.0, 0.1}}, {"radial_bins", 2}, {"height_bins", 2}, {"interval", 0.001}, {"to_time", 0.0095}};
  return {{"name", "flight"},
          {"gravity", {0, 0, 0}},
          {"materials", {{"grain", {{"density", 2500.0}, {"stiffness", 1e5}, {"restitution", 0.5}, {"reference_radius", kR}}}}},
          {"balls", balls},
          {"integrator", {{"scheme", "velocity_verlet"}}},
          {"time", {{"dt", 1e-5}, {"duration", 0.02}}},
          {"output", {{"probes", json::array({probe})}}}};
}

}  // namespace

TEST(VelocityFieldProbe, GivesTheMeanVelocityAndSolidFractionOfGrainsInFlight) {
  const fs::path out = fs::temp_directory_path() / "silodem_velocity_field_flight";
  fs::remove_all(out);  // the test's own scratch
  const json s = silodem::run_case(silodem::load_case(flight_case()), {out, false, false});
  // Samples at t = 0, 0.001, ..., 0.009: ten frames, to_time 0.0095 ends them.
  EXPECT_EQ(s["probes"]["field"]["frames"].get<double>(), 10.0);
  std::ifstream in(out / "probes" / "field.csv");
  std::string line;
  std::getline(in, line);
  ASSERT_EQ(line, "radial_bin,height_bin,r_centre,z_centre,samples,mean_vz,mean_vr,solid_fraction");
  const double grain_volume = 4.0 / 3.0 * std::numbers::pi * kR * kR * kR;
  const auto ring = [](int ir) { return std::numbers::pi * 0.01 * 0.01 * (2.0 * ir + 1.0) * 0.05; };
  // (samples, mean vz, mean vr, grains in the cell) per cell, radial bin fastest.
  const double expected[4][4] = {{10, -0.1, 0.0, 1}, {20, -0.4, 0.0, 2}, {10, 0.4, 0.0, 1}, {0, 0.0, 0.0, 0}};
  for (int k = 0; k < 4; ++k) {
    ASSERT_TRUE(std::getline(in, line)) << k;
    std::stringstream row(line);
    double v[8];
    for (double& x : v) {
      std::string cell;
      std::getline(row, cell, ',');
      x = std::stod(cell);
    }
    EXPECT_EQ(v[0], k % 2) << line;
    EXPECT_EQ(v[1], k / 2) << line;
    EXPECT_EQ(v[4], expected[k][0]) << line;
    EXPECT_NEAR(v[5], expected[k][1], 1e-12) << line;
    // b moves out at 0.2 along y and c in at 0.2 along x: the radial mean of ring 1 is 0 only if
    // each is taken along its own radius.
    EXPECT_NEAR(v[6], expected[k][2], 1e-12) << line;
    EXPECT_NEAR(v[7], expected[k][3] * grain_volume / ring(k % 2), 1e-12) << line;
  }
}
