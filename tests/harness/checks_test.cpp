// The restitution check's two oracles on the reference codes' scheme (velocity Verlet, half-step
// dashpot): "as_integrated" (default) compares with the lagged-dashpot closed form, "exact" with the
// paper's law. The same measured e must sit close to the first and a few per cent below the second
// at ζ = 0.9, Δt = t_c/50: the lag is a first-order change of the law, not a small error.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "harness/verify.hpp"
#include "references/restitution.hpp"
#include "silodem/case/case_error.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

/// collision_restitution.json cut down to the eight phases of the equal ζ = 0.9 pair, clamped,
/// onset-corrected, with the reference codes' scheme and the two restitution checks.
json half_step_case(const std::string& oracle_of_second_check) {
  std::ifstream in(fs::path(SILODEM_SOURCE_DIR) / "cases" / "collision_restitution.json");
  json c = json::parse(in);
  c.erase("compare");
  json balls = json::array(), probes = json::array();
  for (const auto& b : c["balls"])
    if (b["id"].get<std::string>().rfind("z090_equal_", 0) == 0) balls.push_back(b);
  for (const auto& p : c["output"]["probes"])
    if (p["name"].get<std::string>().rfind("z090_equal_", 0) == 0) probes.push_back(p);
  c["balls"] = balls;
  c["output"]["probes"] = probes;
  c["contact"] = {{"clamp_tensile_force", true}, {"onset_correction", true}};
  c["integrator"] = {{"scheme", "velocity_verlet"}, {"dashpot_velocity", "half_step"}};
  c["time"]["dt"] = c["verify"]["variants"]["dt"]["tc_50"]["time"]["dt"];
  c["verify"] = {{"checks", json::array({{{"type", "restitution"}, {"tolerance", 1.0}},
                                         {{"type", "restitution"}, {"tolerance", 1.0},
                                          {"oracle", oracle_of_second_check}}})}};
  return c;
}

fs::path write(const json& c, const std::string& name) {
  const fs::path p = fs::temp_directory_path() / ("silodem_test_checks_" + name + ".json");
  std::ofstream(p) << c.dump();
  return p;
}

}  // namespace

TEST(RestitutionCheck, ExactOracleCountsTheLaggedDashpotAsError) {
  harness::VerifyOptions opt;
  opt.out_root = fs::temp_directory_path() / "silodem_test_checks";
  fs::remove_all(opt.out_root);  // the test's own scratch: a leftover of another build is not silodem's to keep
  opt.progress = false;
  const auto v = harness::verify_cases({write(half_step_case("exact"), "exact")}, opt);
  std::vector<const harness::CheckRow*> rows;
  for (const auto& r : v.rows)
    if (r.quantity == "restitution") rows.push_back(&r);
  ASSERT_EQ(rows.size(), 16u);  // 8 phases × 2 checks, in check order
  // The closed forms in units m_eff = k = 1 (ζ = c/2), Δt = t_c/50 of the undamped pair (Ω = π/50);
  // references/ is checked against theory in tests/references.
  const double exact = references::kelvin_voigt_collision(1.0, 1.8, 1.0, true).restitution;
  const double lagged = references::kelvin_voigt_collision_lagged(1.0, 1.8, 1.0, true, M_PI / 50.0).restitution;
  EXPECT_NEAR(lagged / exact - 1.0, -0.0367, 5e-4);
  for (int k = 0; k < 8; ++k) {
    const auto& as_integrated = *rows[std::size_t(k)];
    const auto& against_exact = *rows[std::size_t(k + 8)];
    EXPECT_EQ(as_integrated.subject, against_exact.subject);
    EXPECT_DOUBLE_EQ(as_integrated.measured, against_exact.measured);
    EXPECT_NEAR(as_integrated.expected, lagged, 1e-9);
    EXPECT_NEAR(against_exact.expected, exact, 1e-9);
    // Onset-corrected: within 0.2 % of the lagged form, 3-4 % below the exact one.
    EXPECT_LT(std::abs(as_integrated.error), 2e-3) << as_integrated.subject;
    EXPECT_GT(against_exact.error, -0.04) << against_exact.subject;
    EXPECT_LT(against_exact.error, -0.033) << against_exact.subject;
  }
}

TEST(RestitutionCheck, UnknownOracleIsRefusedNamingTheKey) {
  try {
    (void)harness::validate_verification(write(half_step_case("lagged"), "bad"));
    FAIL() << "an unknown oracle was accepted";
  } catch (const silodem::CaseError& e) {
    EXPECT_NE(std::string(e.what()).find("oracle"), std::string::npos) << e.what();
  }
}
