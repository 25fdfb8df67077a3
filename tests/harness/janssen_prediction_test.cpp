// The predicted Janssen column: a column whose wall pressures follow Janssen's law with known K and
// μ_w comes back at ratio 1 when the material tests measured those; the tolerance is the first-order
// effect of their scatter, checked against the ratio that a prediction off by one scatter gives; a
// missing material test is refused before anything runs.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "harness/janssen_prediction.hpp"
#include "harness/verify.hpp"
#include "silodem/case/case_error.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr double kD = 0.18, kH = 0.95, kZTop = 0.72, kMass = 22.0, kK = 0.7, kMu = 0.3;

double gamma_of_column() { return kMass * 9.81 / (std::numbers::pi * 0.25 * kD * kD * kZTop); }

double janssen(double K, double mu, double depth) {
  return gamma_of_column() * kD / (4.0 * mu) * (1.0 - std::exp(-4.0 * mu * K * depth / kD));
}

/// A column at rest with Janssen's wall pressures (K, μ_w) on a mantle probe, and the floor at p_h/K.
harness::ResultSet janssen_column(const fs::path& dir) {
  fs::remove_all(dir);  // the test's own scratch
  fs::create_directories(dir / "probes");
  const int bins = 38, angles = 4;
  std::ofstream csv(dir / "probes" / "mantle.csv");
  csv.precision(17);
  csv << "angle_bin,height_bin,angle_lo,angle_hi,along_lo,along_hi,area,pressure_mean,shear_mean,pressure_final,"
         "shear_final\n";
  for (int h = 0; h < bins; ++h) {
    const double z_mid = (h + 0.5) * kH / bins;
    const double p = z_mid < kZTop ? janssen(kK, kMu, kZTop - z_mid) : 0.0;
    for (int a = 0; a < angles; ++a) csv << a << ',' << h << ",0,0,0,0,0.01,0,0," << p << ",0\n";
  }
  csv.close();
  std::ofstream floor(dir / "probes" / "floor.csv");
  floor.precision(17);
  floor << "angle_bin,height_bin,angle_lo,angle_hi,along_lo,along_hi,area,pressure_mean,shear_mean,pressure_final,"
           "shear_final\n";
  const double area = std::numbers::pi * 0.25 * kD * kD;
  floor << "0,0,0,0,0,0," << area << ",0,0," << janssen(kK, kMu, kZTop) / kK << ",0\n";
  floor.close();
  json geometry = {{"diameter", kD}, {"height", kH}, {"centre", {0, 0, 0}}};
  json summary = {{"probes", {{"mantle", {{"file", "mantle.csv"}, {"geometry", geometry}}},
                              {"floor", {{"file", "floor.csv"}, {"geometry", geometry}}}}},
                  {"fill", {{"z_top", kZTop}, {"mobile_mass", kMass}}}};
  return {dir, summary};
}

/// The spread rows a material test leaves: mean (expected) and scatter (measured) for one group.
harness::CheckRow spread(const std::string& case_name, const std::string& quantity, double mean, double scatter) {
  harness::CheckRow r;
  r.case_name = case_name;
  r.variant = "mu=0.5,rolling=none";
  r.quantity = quantity + "_spread";
  r.expected = mean;
  r.measured = scatter;
  r.note = "3 realisations";
  return r;
}

const json kSpec = {{"wall_probe", "mantle"}, {"floor_probe", "floor"}, {"lateral_pressure_ratio_from", "k_test"},
                    {"wall_friction_from", "mu_test"}, {"coverage", 2.0}, {"exclude_bottom_diameters", 0.5}};

const harness::CheckRow& find(const std::vector<harness::CheckRow>& rows, const std::string& q) {
  for (const auto& r : rows)
    if (r.quantity == q) return r;
  throw std::runtime_error("no row " + q);
}

}  // namespace

TEST(JanssenPrediction, AColumnOfTheMeasuredKAndMuWMatchesAndTheToleranceIsTheScattersEffect) {
  silodem::CaseConfig cfg;
  cfg.gravity = silodem::Vec3(0, 0, -9.81);
  const auto rs = janssen_column(fs::temp_directory_path() / "silodem_test_janssen_prediction");
  const double sK = 0.03, sMu = 0.02;
  const std::vector<harness::CheckRow> tests = {spread("k_test", "lateral_pressure_ratio_K", kK, sK),
                                                spread("mu_test", "wall_friction_mu_w", kMu, sMu)};
  const harness::RunContext ctx{cfg, rs, "mu=0.5,rolling=none", "silodem", &tests};
  const auto rows = harness::janssen_prediction(kSpec, ctx);
  const auto& profile = find(rows, "janssen_predicted_profile");
  EXPECT_EQ(profile.verdict(), "pass");
  EXPECT_NEAR(profile.measured, 1.0, 1e-12);
  const auto& floor = find(rows, "janssen_predicted_floor_stress");
  EXPECT_EQ(floor.verdict(), "report");  // Janssen's uniform sigma_v: measured, not judged
  EXPECT_NEAR(floor.error, 0.0, 1e-12);
  // The tolerance is 2 σ, σ the first-order effect of the scatters: each scatter alone against the
  // ratio that a prediction off by that scatter gives the same column.
  for (int which = 0; which < 2; ++which) {
    const std::vector<harness::CheckRow> one = {spread("k_test", "lateral_pressure_ratio_K", kK, which == 0 ? sK : 1e-12),
                                                spread("mu_test", "wall_friction_mu_w", kMu, which == 1 ? sMu : 1e-12)};
    const harness::RunContext c1{cfg, rs, "mu=0.5,rolling=none", "silodem", &one};
    const double tol = find(harness::janssen_prediction(kSpec, c1), "janssen_predicted_profile").tolerance;
    // The same column judged by a prediction off by one scatter: its ratio moves by about σ = tol/2.
    const std::vector<harness::CheckRow> off = {
        spread("k_test", "lateral_pressure_ratio_K", kK + (which == 0 ? sK : 0.0), 1e-12),
        spread("mu_test", "wall_friction_mu_w", kMu + (which == 1 ? sMu : 0.0), 1e-12)};
    const harness::RunContext c2{cfg, rs, "mu=0.5,rolling=none", "silodem", &off};
    const double moved = std::abs(find(harness::janssen_prediction(kSpec, c2), "janssen_predicted_profile").measured - 1.0);
    EXPECT_NEAR(moved, tol / 2.0, 0.1 * tol / 2.0) << (which == 0 ? "K" : "mu_w");  // first order: within 10 %
  }
  // A column whose K is 20 % off the measured one fails.
  const std::vector<harness::CheckRow> wrong = {spread("k_test", "lateral_pressure_ratio_K", 0.8 * kK, sK),
                                                spread("mu_test", "wall_friction_mu_w", kMu, sMu)};
  const harness::RunContext c3{cfg, rs, "mu=0.5,rolling=none", "silodem", &wrong};
  EXPECT_EQ(find(harness::janssen_prediction(kSpec, c3), "janssen_predicted_profile").verdict(), "fail");
}

TEST(JanssenPrediction, KFactorScalesTheTestsKAndTheColumnsScatterAddsInQuadrature) {
  silodem::CaseConfig cfg;
  cfg.gravity = silodem::Vec3(0, 0, -9.81);
  const auto rs = janssen_column(fs::temp_directory_path() / "silodem_test_janssen_prediction_factor");
  // The test measured K_o = K/1.1: with K_factor 1.1 the column of K comes back at ratio 1.
  const std::vector<harness::CheckRow> tests = {spread("k_test", "lateral_pressure_ratio_K", kK / 1.1, 0.03 / 1.1),
                                                spread("mu_test", "wall_friction_mu_w", kMu, 0.02)};
  const harness::RunContext ctx{cfg, rs, "mu=0.5,rolling=none", "silodem", &tests};
  json spec = kSpec;
  const double base_tol = find(harness::janssen_prediction(spec, ctx), "janssen_predicted_profile").tolerance;
  spec["K_factor"] = 1.1;
  spec["K_factor_source"] = {{"type", "published"}, {"citation", "EN 1991-4 C.6"}};
  const harness::CheckRow scaled = find(harness::janssen_prediction(spec, ctx), "janssen_predicted_profile");
  EXPECT_NEAR(scaled.measured, 1.0, 1e-12);
  EXPECT_EQ(scaled.verdict(), "pass");
  EXPECT_NE(scaled.tolerance_source.find("EN 1991-4 C.6"), std::string::npos);
  // The column's own scatter widens the tolerance in quadrature.
  const double tests_tol = scaled.tolerance;
  spec["column_scatter"] = 0.03;
  const double widened = find(harness::janssen_prediction(spec, ctx), "janssen_predicted_profile").tolerance;
  EXPECT_NEAR(widened, std::hypot(tests_tol, 2.0 * 0.03), 1e-12);
  EXPECT_GT(base_tol, 0.0);
}

TEST(JanssenPrediction, AVariantNoMaterialTestMatchesFailsNamingIt) {
  silodem::CaseConfig cfg;
  cfg.gravity = silodem::Vec3(0, 0, -9.81);
  const auto rs = janssen_column(fs::temp_directory_path() / "silodem_test_janssen_prediction_unmatched");
  const std::vector<harness::CheckRow> tests = {spread("k_test", "lateral_pressure_ratio_K", kK, 0.03),
                                                spread("mu_test", "wall_friction_mu_w", kMu, 0.02)};
  const harness::RunContext ctx{cfg, rs, "mu=0.3,rolling=none", "silodem", &tests};
  const auto rows = harness::janssen_prediction(kSpec, ctx);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].verdict(), "fail");
  EXPECT_NE(rows[0].note.find("k_test"), std::string::npos) << rows[0].note;
}

TEST(JanssenPrediction, VerifyRefusesAColumnWithoutItsMaterialTestsBeforeAnyRun) {
  harness::VerifyOptions opt;
  opt.out_root = fs::temp_directory_path() / "silodem_test_janssen_prediction_refused";
  bool ran = false;
  opt.before_first_run = [&] { ran = true; };
  const fs::path cases = fs::path(SILODEM_SOURCE_DIR) / "cases";
  try {
    harness::verify_cases({cases / "janssen_frictional.json", cases / "wall_friction.json"}, opt);
    FAIL() << "accepted a column without its K test";
  } catch (const silodem::CaseError& e) {
    EXPECT_NE(std::string(e.what()).find("lateral_pressure_ratio"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("give its file too"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(ran);
}

TEST(JanssenPrediction, TheEnRouteTakesKFromTheShearTestsAngleOfInternalFriction) {
  silodem::CaseConfig cfg;
  cfg.gravity = silodem::Vec3(0, 0, -9.81);
  const auto rs = janssen_column(fs::temp_directory_path() / "silodem_test_janssen_prediction_en");
  // The angle for which EN 1991-4's 1.1 (1 − sin φ) is the column's K: the EN route comes back at 1;
  // the K test's route, told a K 10 % off, does not.
  const double phi_deg = std::asin(1.0 - kK / 1.1) * 180.0 / std::numbers::pi, s_phi = 1.0;
  const std::vector<harness::CheckRow> tests = {spread("k_test", "lateral_pressure_ratio_K", 0.9 * kK, 0.01),
                                                spread("mu_test", "wall_friction_mu_w", kMu, 0.01),
                                                spread("shear_test", "internal_friction_peak_deg", phi_deg, s_phi)};
  const harness::RunContext ctx{cfg, rs, "mu=0.5,rolling=none", "silodem", &tests};
  json spec = kSpec;
  spec["internal_friction_from"] = "shear_test";
  const auto rows = harness::janssen_prediction(spec, ctx);
  const auto& en = find(rows, "janssen_predicted_profile_en_K");
  EXPECT_NEAR(en.measured, 1.0, 1e-12);
  EXPECT_EQ(en.verdict(), "pass");
  EXPECT_EQ(find(rows, "janssen_predicted_profile").verdict(), "fail");
  // Its tolerance carries σ_K = 1.1 cos φ σ_φ: a prediction with K + σ_K moves the ratio by about tol/2.
  const double sK = 1.1 * std::cos(phi_deg * std::numbers::pi / 180.0) * s_phi * std::numbers::pi / 180.0;
  const std::vector<harness::CheckRow> off = {spread("k_test", "lateral_pressure_ratio_K", kK + sK, 1e-12),
                                              spread("mu_test", "wall_friction_mu_w", kMu, 1e-12)};
  const harness::RunContext c2{cfg, rs, "mu=0.5,rolling=none", "silodem", &off};
  const double moved = std::abs(find(harness::janssen_prediction(kSpec, c2), "janssen_predicted_profile").measured - 1.0);
  const std::vector<harness::CheckRow> phi_only = {spread("k_test", "lateral_pressure_ratio_K", kK, 0.01),
                                                   spread("mu_test", "wall_friction_mu_w", kMu, 1e-12),
                                                   spread("shear_test", "internal_friction_peak_deg", phi_deg, s_phi)};
  const harness::RunContext c3{cfg, rs, "mu=0.5,rolling=none", "silodem", &phi_only};
  const double tol = find(harness::janssen_prediction(spec, c3), "janssen_predicted_profile_en_K").tolerance;
  EXPECT_NEAR(moved, tol / 2.0, 0.1 * tol / 2.0);
  // Without the shear test's rows the whole prediction fails naming what is missing.
  const std::vector<harness::CheckRow> none = {spread("k_test", "lateral_pressure_ratio_K", kK, 0.01),
                                               spread("mu_test", "wall_friction_mu_w", kMu, 0.01)};
  const harness::RunContext c4{cfg, rs, "mu=0.5,rolling=none", "silodem", &none};
  const auto missing = harness::janssen_prediction(spec, c4);
  ASSERT_EQ(missing.size(), 1u);
  EXPECT_EQ(missing[0].verdict(), "fail");
  EXPECT_NE(missing[0].note.find("internal_friction_peak_deg"), std::string::npos) << missing[0].note;
}
