// The mill checks (harness/mill_checks.hpp) on cases/ball_mill.json cut to one speed and 1 s: the
// drum's mean torque meets the charge's angular-momentum balance M (<x> - c) x g - dL/tau within
// the sampled means' end terms, the power is -Omega T to round-off, and the same check fails when
// the torque is off by 1 % (it can fail); the refusals name their keys.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "harness/checks.hpp"
#include "harness/mill_checks.hpp"
#include "harness/verify.hpp"
#include "silodem/case/case_loader.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json short_mill() {
  std::ifstream in(fs::path(SILODEM_SOURCE_DIR) / "cases" / "ball_mill.json");
  json c = json::parse(in);
  c["time"]["duration"] = 1.0;
  for (auto& p : c["output"]["probes"]) p["from_time"] = 0.5;
  json speed = c["verify"]["variants"]["speed"];
  c["verify"]["variants"]["speed"] = {{"w0_72", speed["w0_72"]}};
  return c;
}

}  // namespace

TEST(MillChecks, TheDrumTorqueMeetsTheChargesMomentumBalanceAndTheCheckCanFail) {
  const fs::path file = fs::temp_directory_path() / "silodem_test_mill.json";
  std::ofstream(file) << short_mill().dump();
  harness::VerifyOptions opt;
  opt.out_root = fs::temp_directory_path() / "silodem_test_mill";
  fs::remove_all(opt.out_root);  // the test's own scratch
  opt.progress = false;
  const auto v = harness::verify_cases({file}, opt);
  const harness::CheckRow* torque = nullptr;
  const harness::CheckRow* power = nullptr;
  for (const auto& r : v.rows) {
    if (r.quantity == "drum_torque") torque = &r;
    if (r.quantity == "drum_power") power = &r;
  }
  ASSERT_NE(torque, nullptr);
  ASSERT_NE(power, nullptr);
  EXPECT_TRUE(torque->pass) << torque->error << " against " << torque->tolerance;
  EXPECT_LT(torque->tolerance, 2e-3) << "the bound is tight enough to mean something";
  EXPECT_LT(torque->expected, -100.0) << "the charge rides up the rising side and loads the drum against its turn";
  EXPECT_TRUE(power->pass) << power->error;
  // The same result with the drum's mean torque 1 % off fails.
  const silodem::CaseConfig cfg = silodem::load_case(short_mill());
  fs::path dir;
  for (const auto& e : fs::recursive_directory_iterator(opt.out_root))
    if (e.path().filename() == "summary.json") dir = e.path().parent_path();
  harness::ResultSet result = harness::read_result(dir);
  for (auto& t : result.summary["probes"]["drum_load"]["torque_mean"]) t = t.get<double>() * 1.01;
  const harness::RunContext ctx{cfg, result, "w0_72"};
  const auto rows = harness::torque_identity({{"wall_probe", "drum_load"}, {"charge_probe", "charge"}}, ctx);
  EXPECT_FALSE(rows.at(0).pass);
}

TEST(MillChecks, ATorqueIdentityNeedsATurningWallAndTheChargesWindow) {
  const auto refusal = [](const json& c) -> std::string {
    try {
      silodem::load_case(c);
      harness::validate_check(c["verify"]["checks"][0], "$.verify.checks[0]", silodem::load_case(c), {});
    } catch (const std::exception& e) {
      return e.what();
    }
    return "";
  };
  json c = short_mill();
  c["verify"].erase("variants");
  EXPECT_EQ(refusal(c), "");
  json still = c;
  still["walls"][0].erase("motion");
  EXPECT_NE(refusal(still).find("does not turn"), std::string::npos) << refusal(still);
  json window = c;
  window["output"]["probes"][0]["from_time"] = 0.6;
  EXPECT_NE(refusal(window).find("$.verify.checks[0].wall_probe: its window must be the charge probe's"), std::string::npos)
      << refusal(window);
}

// The tray check (harness/tray_checks.hpp) on cases/vibrating_tray.json at 9 Hz, cut to 1 s: every
// grain is in the tray or counted out (judged exactly), and the slots' masses add up to the outflow
// probe's total (each exit goes to one slot).
TEST(TrayChecks, EveryGrainIsInTheTrayOrCountedOutThroughOneSlot) {
  std::ifstream in(fs::path(SILODEM_SOURCE_DIR) / "cases" / "vibrating_tray.json");
  json c = json::parse(in);
  c["time"]["duration"] = 1.0;
  c["verify"]["variants"] = {{"frequency", {{"f9", json::object()}}}};
  c["verify"]["checks"][0]["from_time"] = 0.5;
  const fs::path file = fs::temp_directory_path() / "silodem_test_tray.json";
  std::ofstream(file) << c.dump();
  harness::VerifyOptions opt;
  opt.out_root = fs::temp_directory_path() / "silodem_test_tray";
  fs::remove_all(opt.out_root);  // the test's own scratch
  opt.progress = false;
  const auto v = harness::verify_cases({file}, opt);
  double through_slots = 0.0;
  int slots = 0;
  const harness::CheckRow* count = nullptr;
  for (const auto& r : v.rows) {
    if (r.quantity == "slot_mass_rate") ++slots, through_slots += std::stod(r.note);
    if (r.quantity == "grain_count") count = &r;
  }
  ASSERT_NE(count, nullptr);
  EXPECT_TRUE(count->pass);
  EXPECT_EQ(slots, 3);
  fs::path dir;
  for (const auto& e : fs::recursive_directory_iterator(opt.out_root))
    if (e.path().filename() == "summary.json") dir = e.path().parent_path();
  const json s = json::parse(std::ifstream(dir / "summary.json"));
  EXPECT_GT(s["probes"]["out"]["exits"].get<long>(), 0);
  EXPECT_NEAR(through_slots, s["probes"]["out"]["mass"].get<double>(), 1e-5 * through_slots);
}
