// The direct shear check on a probe history whose stress ratio is known: τ/σ rises to a peak of
// 0.8 at 3 mm of travel and falls to a critical state of 0.6 from 8 mm on; the check gives back
// atan 0.8 (to the running mean's smoothing of a smooth peak) and atan 0.6 exactly, with the sign
// of τ taken against the ring's motion whatever its direction.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "harness/material_checks.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr double kStart = 0.5, kSpeed = 0.02, kTravel = 0.02, kSigma = 40.0;  // s, m/s, m, N

/// τ/σ along the travel s (m): 0.3 at rest, a parabola to 0.8 at 3 mm, down to 0.6 at 8 mm, flat after.
double ratio(double s) {
  if (s < 0.003) return 0.3 + 0.5 * (1.0 - std::pow((0.003 - s) / 0.003, 2));
  if (s < 0.008) return 0.8 - 0.2 * (s - 0.003) / 0.005;
  return 0.6;
}

harness::ResultSet shear_result(const fs::path& dir, const silodem::Vec3& dir_of_motion) {
  fs::remove_all(dir);  // the test's own scratch
  fs::create_directories(dir / "probes");
  std::ofstream csv(dir / "probes" / "plane.csv");
  csv.precision(17);
  csv << "t,fx,fy,fz,mobile_above,mobile_mass_above\n";
  for (int i = 0; i <= 1500; ++i) {  // every millisecond to t = 1.5 s
    const double t = 0.001 * i, s = std::max(0.0, kSpeed * (t - kStart));
    const silodem::Vec3 f = -ratio(s) * kSigma * dir_of_motion;  // the material below holds the body above back
    csv << t << ',' << f.x() << ',' << f.y() << ',' << kSigma << ",100,1\n";
  }
  csv.close();
  return {dir, {{"probes", {{"plane", {{"file", "plane.csv"}}}}}}};
}

silodem::CaseConfig shear_box(const silodem::Vec3& velocity) {
  silodem::CaseConfig cfg;
  silodem::StageEvent e;
  e.time = kStart, e.type = "move_wall", e.wall = "upper", e.velocity = velocity;
  cfg.events.push_back(e);
  return cfg;
}

double row(const std::vector<harness::CheckRow>& rows, const std::string& q) {
  for (const auto& r : rows)
    if (r.quantity == q) return r.measured;
  return NAN;
}

double deg(double mu) { return std::atan(mu) * 180.0 / std::numbers::pi; }

}  // namespace

TEST(DirectShear, GivesBackThePeakAndCriticalStateAnglesOfAKnownHistory) {
  const json spec = {{"section_probe", "plane"}, {"moving_wall", "upper"}, {"smoothing", 0.001}, {"critical_from", 0.5}};
  for (const silodem::Vec3& dir : {silodem::Vec3(1, 0, 0), silodem::Vec3(0, -1, 0), silodem::Vec3(0.6, 0.8, 0)}) {
    const silodem::CaseConfig cfg = shear_box(kSpeed * dir);
    const auto rs = shear_result(fs::temp_directory_path() / "silodem_test_direct_shear", dir);
    const harness::RunContext ctx{cfg, rs, "v"};
    const auto rows = harness::direct_shear(spec, ctx);
    // The running mean over 1 mm of a parabola's top (curvature 0.5 / 3 mm², one side) and the
    // ramp after it stays within 0.012 of its 0.8; the critical state is flat: exact.
    EXPECT_NEAR(row(rows, "internal_friction_peak_deg"), deg(0.8), deg(0.8) - deg(0.788));
    EXPECT_LT(row(rows, "internal_friction_peak_deg"), deg(0.8) + 1e-12);
    EXPECT_NEAR(row(rows, "internal_friction_critical_deg"), deg(0.6), 1e-9);
    for (const auto& r : rows) EXPECT_EQ(r.verdict(), "report") << r.quantity;
  }
}

TEST(DirectShear, ARunThatNeverReachesTheShearGivesNoValueAndSaysWhy) {
  const json spec = {{"section_probe", "plane"}, {"moving_wall", "upper"}};
  const silodem::CaseConfig cfg = shear_box(silodem::Vec3(kSpeed, 0, 0));
  auto rs = shear_result(fs::temp_directory_path() / "silodem_test_direct_shear_short", silodem::Vec3(1, 0, 0));
  // Rows only up to the shear's start.
  std::ofstream csv(rs.dir / "probes" / "plane.csv");
  csv << "t,fx,fy,fz,mobile_above,mobile_mass_above\n0,0,0,40,100,1\n0.4,0,0,40,100,1\n";
  csv.close();
  const harness::RunContext ctx{cfg, rs, "v"};
  const auto rows = harness::direct_shear(spec, ctx);
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& r : rows) {
    EXPECT_TRUE(std::isnan(r.measured)) << r.quantity;
    EXPECT_NE(r.reason.find("no rows along the shear"), std::string::npos) << r.reason;
  }
}
