// The grinding check (harness/grinding_checks.hpp) on a break log written by hand for the ball
// mill's charge (25 ore grains of r = 0.1 m): the size distribution it rebuilds against the same
// sums done by hand, the end count judged against the charge probe's (and failing when it differs),
// and a log that breaks a grain the charge does not have refused with the file named.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "harness/grinding_checks.hpp"
#include "harness/result_files.hpp"
#include "silodem/case/case_loader.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const json kSpec = {{"material", "ore"}, {"every", 2.5}, {"sieves", {0.09, 0.065, 0.051}}, {"charge_probe", "charge"}};

silodem::CaseConfig grinding_case() {
  std::ifstream in(fs::path(SILODEM_SOURCE_DIR) / "cases" / "ball_mill_grinding.json");
  json c = json::parse(in);
  c.erase("verify");
  return silodem::load_case(c);
}

/// A result whose log breaks one ore grain into 4 at 2 s and one of those into 2 at 3 s.
harness::ResultSet result(const std::string& log, double final_balls) {
  const fs::path dir = fs::temp_directory_path() / "silodem_test_grinding";
  fs::remove_all(dir);  // the test's own scratch
  fs::create_directories(dir);
  std::ofstream(dir / "breakage.csv") << "t,tag,radius,accumulated_energy,toughness,fragments\n" << log;
  json summary = {{"run", {{"time", 5.0}}}, {"probes", {{"charge", {{"final", {{"balls", final_balls}}}}}}}};
  return harness::ResultSet{dir, summary};
}

double measured(const std::vector<harness::CheckRow>& rows, const std::string& quantity, const std::string& subject) {
  for (const auto& r : rows)
    if (r.quantity == quantity && r.subject == subject) return r.measured;
  ADD_FAILURE() << "no row " << quantity << " / " << subject;
  return NAN;
}

const std::string kLog = "2.0,7,0.1,30,20,4\n3.0,1000000001,0.0629960524947,12,10,2\n";

}  // namespace

TEST(GrindingChecks, TheSizeDistributionFollowsTheBreakLogAndTheEndCountIsJudged) {
  const silodem::CaseConfig cfg = grinding_case();
  const harness::ResultSet res = result(kLog, 97 + 3 + 1);
  const harness::RunContext ctx{cfg, res, "base"};
  const auto rows = harness::size_distribution(kSpec, ctx);
  // By hand: 25 grains of equal mass; 4 pieces of r 0.1/4^(1/3) = 0.063 m, one of which becomes two of 0.05 m.
  EXPECT_EQ(measured(rows, "grains", "ore at 0 s"), 25.0);
  EXPECT_EQ(measured(rows, "mass_fraction_passing", "ore at 0 s, r < 0.09 m"), 0.0);
  EXPECT_EQ(measured(rows, "grains", "ore at 2.5 s"), 28.0);
  EXPECT_NEAR(measured(rows, "mass_fraction_passing", "ore at 2.5 s, r < 0.065 m"), 1.0 / 25.0, 1e-12);
  EXPECT_EQ(measured(rows, "mass_fraction_passing", "ore at 2.5 s, r < 0.051 m"), 0.0);
  EXPECT_EQ(measured(rows, "grains", "ore at 5 s"), 29.0);
  EXPECT_NEAR(measured(rows, "mass_fraction_passing", "ore at 5 s, r < 0.09 m"), 1.0 / 25.0, 1e-12);
  EXPECT_NEAR(measured(rows, "mass_fraction_passing", "ore at 5 s, r < 0.051 m"), 0.25 / 25.0, 1e-12);
  const harness::CheckRow& count = rows.back();
  EXPECT_EQ(count.quantity, "grains_from_break_log");
  EXPECT_TRUE(count.pass);
  // A charge that counts one grain more than the log gives fails.
  const harness::ResultSet off = result(kLog, 97 + 3 + 2);
  EXPECT_FALSE(harness::size_distribution(kSpec, harness::RunContext{cfg, off, "base"}).back().pass);
}

TEST(GrindingChecks, ALogThatBreaksAGrainTheChargeDoesNotHaveIsRefused) {
  const silodem::CaseConfig cfg = grinding_case();
  const harness::ResultSet res = result("2.0,7,0.07,30,20,4\n", 100);
  try {
    (void)harness::size_distribution(kSpec, harness::RunContext{cfg, res, "base"});
    FAIL() << "accepted a break of a 0.07 m grain";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("breakage.csv"), std::string::npos) << e.what();
  }
}
