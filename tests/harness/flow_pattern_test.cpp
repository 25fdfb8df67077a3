// The flow pattern check on velocity sections of known shape: a plug (every ring flows) is mass
// flow, a channel over a resting wall layer is funnel flow; Jenike's boundary in Arnold & McLean's
// form against values worked by hand; the verdict is judged only away from the boundary, and a
// missing material test fails.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "harness/flow_pattern.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

/// A velocity section of 4 rings x 3 bands (z centres -0.01, 0.01, 0.03): ring k of the middle band
/// moves down at axis_speed * profile[k]; the outermost ring is empty (solid fraction 0.05) in every band.
harness::ResultSet section(const fs::path& dir, const double (&profile)[3]) {
  fs::remove_all(dir);  // the test's own scratch
  fs::create_directories(dir / "probes");
  std::ofstream csv(dir / "probes" / "flow.csv");
  csv << "radial_bin,height_bin,r_centre,z_centre,samples,mean_vz,mean_vr,solid_fraction\n";
  for (int h = 0; h < 3; ++h)
    for (int k = 0; k < 4; ++k) {
      const double v = h == 1 && k < 3 ? -0.04 * profile[k] : -0.5;  // other bands: anything
      csv << k << ',' << h << ',' << 0.01 * (k + 0.5) << ',' << -0.01 + 0.02 * h << ",100," << v << ",0,"
          << (k < 3 ? 0.6 : 0.05) << '\n';
    }
  csv.close();
  return {dir, {{"probes", {{"flow", {{"file", "flow.csv"}}}}}}};
}

/// A cylinder of D = 0.18 m on a cone of half-angle beta down to an outlet of 0.063 m.
silodem::CaseConfig hopper(double beta_deg) {
  silodem::CaseConfig cfg;
  silodem::WallSpec cone;
  cone.name = "hopper", cone.type = "cone", cone.diameter = 0.18, cone.hole_diameter = 0.063;
  cone.height = (0.18 - 0.063) / 2.0 / std::tan(beta_deg * std::numbers::pi / 180.0);
  cfg.walls.push_back(cone);
  return cfg;
}

harness::CheckRow spread(const std::string& case_name, const std::string& quantity, double mean) {
  harness::CheckRow r;
  r.case_name = case_name, r.variant = "mu=0.5,rolling=none", r.quantity = quantity + "_spread";
  r.expected = mean, r.measured = 0.3, r.note = "3 realisations";
  return r;
}

const json kSpec = {{"velocity_probe", "flow"}, {"hopper_wall", "hopper"}, {"z", 0.012},
                    {"wall_friction_from", "mu_test"}, {"internal_friction_from", "shear_test"},
                    {"mass_flow_index", 0.3}, {"mass_flow_index_source", {{"type", "published"}, {"citation", "Johanson"}}},
                    {"boundary_source", {{"type", "published"}, {"citation", "Jenike"}}}};

const harness::CheckRow& find(const std::vector<harness::CheckRow>& rows, const std::string& q) {
  for (const auto& r : rows)
    if (r.quantity == q) return r;
  throw std::runtime_error("no row " + q);
}

}  // namespace

TEST(FlowPattern, JenikesConicalBoundaryInArnoldAndMcLeansForm) {
  // delta 50, phi_w 20: (1 - sin 50)/(2 sin 50) = 0.15270, acos = 81.216 deg: 49.392 - 20 = 29.392
  // (Jenike's chart gives about 30 deg there).
  EXPECT_NEAR(harness::conical_mass_flow_boundary_deg(50.0, 20.0), 29.392, 1e-3);
  // delta 23.86, phi_w = atan 0.270 = 15.11: (1 - 0.40446)/0.80892 = 0.73621, acos = 42.59 deg:
  // 0.5 (180 - 42.59) - 15.11 = 53.60.
  EXPECT_NEAR(harness::conical_mass_flow_boundary_deg(23.86, std::atan(0.270) * 180.0 / std::numbers::pi), 53.6, 0.05);
  // Below asin(1/3) the fit has no value.
  EXPECT_TRUE(std::isnan(harness::conical_mass_flow_boundary_deg(19.0, 10.0)));
  EXPECT_FALSE(std::isnan(harness::conical_mass_flow_boundary_deg(19.6, 10.0)));
}

TEST(FlowPattern, APlugIsMassFlowAndAChannelOverARestingWallIsFunnelFlow) {
  const std::vector<harness::CheckRow> tests = {spread("shear_test", "internal_friction_critical_deg", 23.86),
                                                spread("mu_test", "wall_friction_mu_w", 0.270)};
  const double plug[3] = {1.0, 0.9, 0.7}, channel[3] = {1.0, 0.4, 0.01};
  struct Case {
    double beta;
    const double (&profile)[3];
    const char* verdict;
    double index;
  };
  const Case cases[] = {{35.0, plug, "pass", 0.7}, {65.0, channel, "pass", 0.01},
                        {35.0, channel, "fail", 0.01}, {65.0, plug, "fail", 0.7},
                        {52.0, plug, "report", 0.7}};  // within 5 deg of 53.6: not judged
  int k = 0;
  for (const Case& c : cases) {
    const auto rs = section(fs::temp_directory_path() / ("silodem_test_flow_pattern" + std::to_string(k++)), c.profile);
    const silodem::CaseConfig cfg = hopper(c.beta);
    const harness::RunContext ctx{cfg, rs, "mu=0.5,rolling=none,beta=x", "silodem", &tests};
    const auto rows = harness::flow_pattern(kSpec, ctx);
    // The outermost filled ring is ring 2 (ring 3's solid fraction is 0.05), the band the one at z 0.01.
    EXPECT_NEAR(find(rows, "mass_flow_index").measured, c.index, 1e-12) << c.beta;
    EXPECT_NEAR(find(rows, "mass_flow_boundary_deg").measured, 53.6, 0.05);
    EXPECT_NEAR(find(rows, "mass_flow_boundary_deg").expected, c.beta, 1e-9);
    EXPECT_EQ(find(rows, "flow_pattern_is_mass_flow").verdict(), c.verdict) << c.beta << " " << c.index;
  }
}

TEST(FlowPattern, WithoutTheMaterialTestsThePredictionFails) {
  const double plug[3] = {1.0, 0.9, 0.7};
  const auto rs = section(fs::temp_directory_path() / "silodem_test_flow_pattern_missing", plug);
  const silodem::CaseConfig cfg = hopper(35.0);
  const std::vector<harness::CheckRow> only_mu = {spread("mu_test", "wall_friction_mu_w", 0.270)};
  const harness::RunContext ctx{cfg, rs, "mu=0.5,rolling=none", "silodem", &only_mu};
  const auto rows = harness::flow_pattern(kSpec, ctx);
  const auto& r = find(rows, "flow_pattern_is_mass_flow");
  EXPECT_EQ(r.verdict(), "fail");
  EXPECT_NE(r.note.find("shear_test"), std::string::npos) << r.note;
}
