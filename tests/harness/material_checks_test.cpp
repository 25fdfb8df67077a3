// The virtual K test's check on a column whose wall pressures are known: the probe file of a
// column at rest with p_h = K σ_v, σ_v from the weight above less the wall shear above (the slice
// equilibrium the check inverts), gives back K; the wall's share of the weight comes back too.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "harness/material_checks.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct Column {
  double D = 0.08, H = 0.45, z_top = 0.2, mass = 1.4, K = 0.6, shear = 0.0;  // shear: wall traction, Pa
  double mu_w = 0.0;  // the time means: p = K σ_v and τ = μ_w p (the bottom band at 3 μ_w)
  int bins = 18, angles = 4;
};

/// Writes the probe CSV and returns the result set of such a column.
harness::ResultSet column_result(const Column& c, const fs::path& dir) {
  fs::remove_all(dir);  // the test's own scratch
  fs::create_directories(dir / "probes");
  const double area = std::numbers::pi * 0.25 * c.D * c.D, g = 9.81;
  const double gamma = c.mass * g / (area * c.z_top);
  const double band_h = c.H / c.bins, cell_area = std::numbers::pi * c.D * band_h / c.angles;
  std::ofstream csv(dir / "probes" / "mantle.csv");
  csv.precision(17);
  csv << "angle_bin,height_bin,angle_lo,angle_hi,along_lo,along_hi,area,pressure_mean,shear_mean,pressure_final,"
         "shear_final\n";
  for (int h = 0; h < c.bins; ++h) {
    const double z_mid = (h + 0.5) * band_h;
    const bool filled = z_mid < c.z_top;
    // Wall shear c.shear on the filled part; σ_v(z) = γ (z_top − z) − (shear over the wall above z)/A.
    const double wall_above = c.shear * std::numbers::pi * c.D * std::max(0.0, c.z_top - z_mid);
    const double sigma_v = std::max(0.0, gamma * (c.z_top - z_mid) - wall_above / area);
    const double p = filled ? c.K * sigma_v : 0.0, tau = (h == 0 ? 3.0 : 1.0) * c.mu_w * p;
    for (int a = 0; a < c.angles; ++a)
      csv << a << ',' << h << ",0,0,0,0," << cell_area << ',' << p << ',' << tau << ',' << p << ','
          << (filled ? c.shear : 0.0) << '\n';
  }
  csv.close();
  json summary = {{"probes", {{"mantle", {{"file", "mantle.csv"},
                                          {"geometry", {{"diameter", c.D}, {"height", c.H}, {"centre", {0, 0, 0}}}}}}}},
                  {"fill", {{"z_top", c.z_top}, {"mobile_mass", c.mass}}}};
  return {dir, summary};
}

double row(const std::vector<harness::CheckRow>& rows, const std::string& q) {
  for (const auto& r : rows)
    if (r.quantity == q) return r.measured;
  return NAN;
}

}  // namespace

TEST(LateralPressureRatio, GivesBackTheKOfAColumnWithAndWithoutWallShear) {
  silodem::CaseConfig cfg;
  cfg.gravity = silodem::Vec3(0, 0, -9.81);
  const json spec = {{"wall_probe", "mantle"}, {"exclude_bottom_diameters", 0.5}, {"exclude_top_diameters", 0.5}};
  for (const double shear : {0.0, 20.0}) {
    Column c;
    c.shear = shear;
    const auto rs = column_result(c, fs::temp_directory_path() / "silodem_test_lateral_pressure_ratio");
    const harness::RunContext ctx{cfg, rs, "v"};
    const auto rows = harness::lateral_pressure_ratio(spec, ctx);
    // The band midpoints sample the linear σ_v exactly, so K comes back to rounding.
    EXPECT_NEAR(row(rows, "lateral_pressure_ratio_K"), 0.6, 1e-9) << "shear " << shear;
    // The wall's share: shear × the wetted mantle (the bands below z_top, whole) over the weight.
    const double band_h = c.H / c.bins, wetted = std::ceil(c.z_top / band_h) * band_h;
    EXPECT_NEAR(row(rows, "wall_carried_fraction"), shear * std::numbers::pi * c.D * wetted / (c.mass * 9.81), 1e-12);
    for (const auto& r : rows) EXPECT_EQ(r.verdict(), "report") << r.quantity;
  }
}

TEST(WallFriction, GivesBackTheRatioOfShearToPressureOverTheColumnsBands) {
  silodem::CaseConfig cfg;
  cfg.gravity = silodem::Vec3(0, 0, -9.81);
  Column c;
  c.mu_w = 0.37;
  const auto rs = column_result(c, fs::temp_directory_path() / "silodem_test_wall_friction");
  const harness::RunContext ctx{cfg, rs, "v"};
  // The bottom band (3 mu_w) lies in the excluded 0.5 D: mu_w comes back to rounding.
  const json spec = {{"wall_probe", "mantle"}, {"exclude_bottom_diameters", 0.5}, {"exclude_top_diameters", 0.5}};
  const auto rows = harness::wall_friction(spec, ctx);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_NEAR(rows[0].measured, 0.37, 1e-12);
  EXPECT_EQ(rows[0].verdict(), "report");
  // Without the exclusion the bottom band's 3 mu_w weighs in: the sum is force-weighted, so above 0.37.
  const auto all = harness::wall_friction({{"wall_probe", "mantle"}, {"exclude_bottom_diameters", 0.0}}, ctx);
  EXPECT_GT(all[0].measured, 0.38);
  // Nothing between the excluded ends: no value, and the reason.
  const auto none = harness::wall_friction({{"wall_probe", "mantle"}, {"exclude_bottom_diameters", 3.0}}, ctx);
  EXPECT_TRUE(std::isnan(none[0].measured));
}

TEST(Spread, MeanAndSampleDeviationPerGroupAlongTheAxis) {
  // Two groups (mu) of three seeds each: the spread rows hold each group's mean and sample deviation.
  std::vector<harness::CheckRow> rows;
  std::vector<std::pair<std::string, std::string>> groups;
  const double k[2][3] = {{0.5, 0.6, 0.7}, {0.4, 0.4, 0.4}};
  for (int m = 0; m < 2; ++m)
    for (int s = 0; s < 3; ++s) {
      harness::CheckRow r;
      r.variant = "mu=" + std::to_string(m) + ",seed=" + std::to_string(s);
      r.quantity = "lateral_pressure_ratio_K";
      r.subject = "mantle";
      r.measured = k[m][s];
      rows.push_back(r);
      groups.emplace_back(r.variant, "mu=" + std::to_string(m));
    }
  const json spec = {{"axis", "seed"}, {"quantities", {"lateral_pressure_ratio_K"}}};
  const auto out = harness::spread_rows(spec, "case", rows, groups);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].variant, "mu=0");
  EXPECT_NEAR(out[0].expected, 0.6, 1e-15);
  EXPECT_NEAR(out[0].measured, 0.1, 1e-15);
  EXPECT_EQ(out[1].variant, "mu=1");
  EXPECT_NEAR(out[1].measured, 0.0, 1e-15);
  EXPECT_EQ(out[0].quantity, "lateral_pressure_ratio_K_spread");
  EXPECT_EQ(out[0].verdict(), "report");
}

TEST(ColumnFloor, IsTheDiskInsideTheCylinderOrElseItsBase) {
  silodem::CaseConfig cfg;
  const json geometry = {{"centre", {0, 0, -0.02}}, {"height", 0.47}, {"diameter", 0.08}};
  EXPECT_EQ(harness::column_floor(cfg, geometry), -0.02);  // no floor: the cylinder's base
  silodem::WallSpec floor;
  floor.type = "disk";
  floor.centre = silodem::Vec3(0, 0, 0.0);
  silodem::WallSpec gate = floor;  // a gate below the cylinder's base is no floor of the column
  gate.centre = silodem::Vec3(0, 0, -0.03);
  silodem::WallSpec lid = floor;   // a disk higher up is not the lowest
  lid.centre = silodem::Vec3(0, 0, 0.3);
  cfg.walls = {gate, lid, floor};
  EXPECT_EQ(harness::column_floor(cfg, geometry), 0.0);
}
