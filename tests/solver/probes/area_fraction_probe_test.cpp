// The area fraction probe (probes/area_fraction_probe.hpp) on discs at rest on a triangular
// lattice of spacing a (planar mode, no gravity, no contacts): every cell that is a whole number of
// the lattice's rectangular cells (a by sqrt(3) a, two discs) covers 2 pi r^2 / (sqrt(3) a^2) of
// its area, exactly; the empty margin covers nothing; and the loader refuses the probe in 3-D.
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
constexpr double kR = 0.004, kA = 2.2 * kR;
const double kH = std::sqrt(3.0) * kA;  // a rectangular cell's height

json lattice_case() {
  json balls = json::array();
  for (int row = 0; row < 8; ++row)
    for (int col = 0; col < 12; ++col)
      balls.push_back({{"id", "d" + std::to_string(row) + "_" + std::to_string(col)}, {"material", "disc"}, {"radius", kR},
                       {"position", {(col + 0.25 + 0.5 * (row % 2)) * kA, 0.0, (row + 0.5) * 0.5 * kH}}});
  return {{"name", "area_fraction_lattice"},
          {"dimension", 2},
          {"grain_inertia", "disc"},
          {"gravity", {0, 0, 0}},
          {"materials", {{"disc", {{"density", 2500}, {"stiffness", 1e4}, {"restitution", 0.5}, {"reference_radius", kR}}}}},
          {"balls", balls},
          {"time", {{"dt", 1e-5}, {"duration", 1e-3}}},
          // Cells of 3 a by sqrt(3) a over the lattice (4 x 4 cells), and a last column beyond it.
          {"output", {{"probes", {{{"type", "area_fraction"}, {"name", "map"}, {"x", {0.0, 15 * kA}}, {"z", {0.0, 4 * kH}},
                                   {"x_bins", 5}, {"z_bins", 4}, {"interval", 1e-4}}}}}}};
}
}  // namespace

TEST(AreaFractionProbe, ATriangularLatticeCoversTwoPiRSquaredOverRootThreeASquared) {
  const fs::path out = fs::temp_directory_path() / "silodem_area_fraction";
  fs::remove_all(out);  // the test's own scratch
  const json s = silodem::run_case(silodem::load_case(lattice_case()), {out, false, false});
  EXPECT_GT(s["probes"]["map"]["samples"].get<double>(), 5.0);
  const double expected = 2.0 * M_PI * kR * kR / (std::sqrt(3.0) * kA * kA);
  std::ifstream csv(out / "probes" / "map.csv");
  std::string line;
  std::getline(csv, line);
  int full = 0, empty = 0;
  while (std::getline(csv, line)) {
    std::vector<double> v;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) v.push_back(std::stod(cell));
    if (v[0] < 4) {
      EXPECT_NEAR(v[4], expected, 1e-12) << line;
      ++full;
    } else {
      EXPECT_EQ(v[4], 0.0) << line;
      ++empty;
    }
  }
  EXPECT_EQ(full, 16);
  EXPECT_EQ(empty, 4);
}

TEST(AreaFractionProbe, ItIsRefusedOutsideThePlanarMode) {
  json c = lattice_case();
  c.erase("dimension");
  c.erase("grain_inertia");
  try {
    silodem::load_case(c);
    FAIL() << "loaded";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("it needs \"dimension\": 2"), std::string::npos) << e.what();
  }
}
