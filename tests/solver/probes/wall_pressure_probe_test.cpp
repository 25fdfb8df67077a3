// The wall pressure probe on hand-set wall loads: pressure × cell area summed over the cells
// gives back the normal load, shear the load along the wall, cells sit where their balls are.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "silodem/probes/wall_pressure_probe.hpp"
#include "silodem/scene/wall_builders.hpp"

using namespace silodem;

namespace {
struct WallScene {
  WallSpec w;
  Particles p;
};
WallScene make(const std::string& type) {
  WallScene s;
  s.w.name = "w";
  s.w.type = type;
  s.w.material = "m";
  s.w.r_min = s.w.r_max = 0.005;
  s.w.spacing = 0.006;
  s.w.centre = Vec3(0, 0, 0);
  s.w.diameter = 0.1;
  s.w.height = 0.2;
  s.p.add({Vec3(0, 0, 0.05), Vec3::Zero(), 0.004, 1e-3, 1, 0, 0, "grain", 1}, false);
  std::int64_t tag = 1;  // every ball its own tag, as in a case
  for (const auto& b : build_wall(s.w, 1)) s.p.add({b.position, Vec3::Zero(), b.radius, 1.0, 1, 0, 0, b.id, ++tag}, true);
  return s;
}
/// A probe of wall "w" on a grid of angle × height (or radius) cells.
ProbeSpec grid_spec(const std::string& name, int angle_bins, int height_bins) {
  ProbeSpec spec;
  spec.name = name;
  spec.wall = "w";
  spec.angle_bins = angle_bins;
  spec.height_bins = height_bins;
  return spec;
}
std::vector<std::vector<double>> rows(const std::filesystem::path& f) {
  std::ifstream in(f);
  std::string line;
  std::getline(in, line);
  std::vector<std::vector<double>> out;
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    std::vector<double> r;
    for (std::string c; std::getline(ss, c, ',');) r.push_back(std::stod(c));
    out.push_back(r);
  }
  return out;
}
}  // namespace

TEST(WallPressureProbe, CylinderRadialLoadAndShear) {
  WallScene s = make("cylinder");
  // Every wall ball pushed outward with 0.01 N and dragged down with 0.002 N.
  std::size_t n = 0;
  for (std::size_t i = s.p.n_mobile; i < s.p.size(); ++i, ++n) {
    const Vec3 radial = Vec3(s.p.x[i].x(), s.p.x[i].y(), 0).normalized();
    s.p.f[i] = 0.01 * radial + Vec3(0, 0, -0.002);
  }
  WallPressureProbe probe(grid_spec("cyl", 6, 4), s.w);
  probe.sample(s.p, 0.0);
  probe.sample(s.p, 1.0);
  const auto dir = std::filesystem::temp_directory_path();
  const auto digest = probe.write(dir);
  EXPECT_EQ(digest["wall_balls"], n);
  double normal = 0.0, shear = 0.0, area = 0.0;
  for (const auto& r : rows(dir / "cyl.csv")) {
    area += r[6];
    normal += r[7] * r[6];
    shear += r[8] * r[6];
    EXPECT_NEAR(r[7], r[9], 1e-12);  // constant load: mean = final
  }
  EXPECT_NEAR(area, M_PI * 0.1 * 0.2, 1e-12);  // the cells tile the nominal mantle
  EXPECT_NEAR(normal, 0.01 * double(n), 1e-9);
  EXPECT_NEAR(shear, 0.002 * double(n), 1e-9);  // positive: dragged down the wall
}

TEST(WallPressureProbe, DiskCarriesTheWeightAsPressure) {
  WallScene s = make("disk");
  double weight = 0.0;
  for (std::size_t i = s.p.n_mobile; i < s.p.size(); ++i) {
    // A load falling off with radius, as under a Janssen column.
    const double w = 0.01 * (1.0 - std::hypot(s.p.x[i].x(), s.p.x[i].y()) / 0.06);
    s.p.f[i] = Vec3(0, 0, -w);
    weight += w;
  }
  WallPressureProbe probe(grid_spec("disk", 1, 5), s.w);
  probe.sample(s.p, 0.0);
  const auto dir = std::filesystem::temp_directory_path();
  probe.write(dir);
  double load = 0.0, area = 0.0, inner = -1.0, outer = -1.0;
  for (const auto& r : rows(dir / "disk.csv")) {
    load += r[9] * r[6];
    area += r[6];
    if (r[1] == 0) inner = r[9];
    if (r[1] == 4) outer = r[9];
  }
  EXPECT_NEAR(load, weight, 1e-9);
  EXPECT_NEAR(area, M_PI * 0.05 * 0.05, 1e-12);
  EXPECT_GT(inner, outer);  // the load profile shows: more pressure at the centre
}

// A wall moved by a stage event (the frictional column's slip) is no motion law: its balls keep
// the cells of their first location, whenever the balls are renumbered. Before, a renumbering after
// the move binned them where they had gone, so the profile depended on when the sort came.
TEST(WallPressureProbe, AWallBallKeepsItsCellWhenTheWallMovesAndTheBallsAreRenumbered) {
  WallScene s = make("cylinder");
  for (std::size_t i = s.p.n_mobile; i < s.p.size(); ++i) {
    const Vec3 radial = Vec3(s.p.x[i].x(), s.p.x[i].y(), 0).normalized();
    s.p.f[i] = (0.01 + 0.05 * s.p.x[i].z()) * radial;  // a load that grows up the wall: every cell differs
  }
  WallPressureProbe probe(grid_spec("moved", 6, 4), s.w);
  probe.sample(s.p, 0.0);
  const auto before_dir = std::filesystem::temp_directory_path() / "silodem_wpp_before";
  const auto after_dir = std::filesystem::temp_directory_path() / "silodem_wpp_after";
  std::filesystem::create_directories(before_dir);
  std::filesystem::create_directories(after_dir);
  probe.write(before_dir);
  // The wall rises 0.6 of a band (0.03 m); the same balls carry the same loads; then a renumbering.
  for (std::size_t i = s.p.n_mobile; i < s.p.size(); ++i) s.p.x[i].z() += 0.03;
  ++s.p.topology;
  probe.sample(s.p, 1.0);
  probe.write(after_dir);
  const auto before = rows(before_dir / "moved.csv"), after = rows(after_dir / "moved.csv");
  ASSERT_EQ(before.size(), after.size());
  int moved_cells = 0;
  for (std::size_t k = 0; k < before.size(); ++k) {
    EXPECT_DOUBLE_EQ(after[k][9], before[k][9]) << "cell " << k;
    moved_cells += before[k][9] > 0.0;
  }
  EXPECT_EQ(moved_cells, 24) << "every cell carries load";
}
