// Integration: the verification cases run end to end (case file → solver → result files →
// checks against the oracles) and every check passes. Each check compares with a closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <set>

#include <nlohmann/json.hpp>

#include "harness/verify.hpp"
#include "scratch_case.hpp"

namespace fs = std::filesystem;

namespace {
harness::VerifyOutcome run(const std::string& name) {
  harness::VerifyOptions opt;
  opt.out_root = fs::temp_directory_path() / ("silodem_test_" + name);
  fs::remove_all(opt.out_root);  // the test's own scratch: a leftover of another build is not silodem's to keep
  opt.progress = false;
  return harness::verify_cases({fs::path(SILODEM_SOURCE_DIR) / "cases" / (name + ".json")}, opt);
}

std::map<std::string, std::size_t> count_by_quantity(const harness::VerifyOutcome& v) {
  std::map<std::string, std::size_t> n;
  for (const auto& r : v.rows) ++n[r.quantity];
  return n;
}

/// Every judged row passes and something was judged; every other row is a report row with its reason.
void expect_all_pass(const harness::VerifyOutcome& v) {
  std::size_t judged = 0;
  for (const auto& r : v.rows) {
    if (!r.judged()) {
      EXPECT_EQ(r.verdict(), "report") << r.quantity;
      EXPECT_FALSE(r.reason.empty()) << r.quantity;
      continue;
    }
    ++judged;
    EXPECT_FALSE(r.tolerance_source.empty()) << r.quantity;
    EXPECT_TRUE(r.pass) << r.variant << " " << r.quantity << " " << r.subject << ": expected " << r.expected
                        << " measured " << r.measured << " error " << r.error << " tolerance " << r.tolerance
                        << " bound " << r.bound;
  }
  EXPECT_GT(judged, 0u);
  EXPECT_TRUE(v.all_pass());
}

/// The kind of every row of `quantity`.
std::set<std::string> kinds(const harness::VerifyOutcome& v, const std::string& quantity) {
  std::set<std::string> k;
  for (const auto& r : v.rows)
    if (r.quantity == quantity) k.insert(harness::kind_name(r.kind));
  return k;
}
}  // namespace

TEST(Cases, CollisionRestitution) {
  const auto v = run("collision_restitution");
  const auto n = count_by_quantity(v);
  // 20 variants × 192 pairs, restitution and duration; orders for 10 integrator/clamp groups.
  EXPECT_EQ(n.at("restitution"), 20u * 192u);
  EXPECT_EQ(n.at("contact_duration"), 20u * 192u);
  EXPECT_EQ(n.at("restitution_order"), 10u);
  EXPECT_EQ(kinds(v, "restitution"), std::set<std::string>{"match"});  // against the scheme bound
  EXPECT_EQ(kinds(v, "restitution_order"), std::set<std::string>{"bound"});
  EXPECT_EQ(kinds(v, "energy_drift"), std::set<std::string>{"report"});  // its tolerance states no source
  expect_all_pass(v);
}

TEST(Cases, CohesionCutoff) {
  const auto v = run("cohesion_cutoff");
  const auto n = count_by_quantity(v);
  EXPECT_EQ(n.at("escape_speed"), 3u * 2u);
  EXPECT_EQ(n.at("captured_gap/reach"), 3u * 2u);
  // The cohesion rows are judged against the scheme's bound (references/cohesion.hpp).
  for (const char* q : {"escape_speed", "turning_gap", "cohesion_energy_removed"})
    EXPECT_EQ(kinds(v, q), std::set<std::string>{"match"}) << q;
  EXPECT_EQ(kinds(v, "captured_gap/reach"), std::set<std::string>{"bound"});
  expect_all_pass(v);
}

TEST(Cases, FreeFallContact) {
  const auto v = run("free_fall_contact");
  EXPECT_EQ(count_by_quantity(v).at("rebound_height"), 10u);
  expect_all_pass(v);
}

TEST(Cases, JanssenColumn) {
  // Sedimented column at rest: the pressure profile is Janssen-shaped, the deepest band at most
  // the frictionless K γ z (how much less depends on μ_w from wall roughness, which scatters from
  // 0.001 to 0.04 between realisations), K lies where frictionless packings put it, the walls
  // carry the fill's weight.
  const auto v = run("janssen_column");
  std::map<std::string, double> m;
  for (const auto& r : v.rows) m[r.quantity] = r.measured;
  EXPECT_GT(m.at("janssen_fit_r2"), 0.95);
  EXPECT_GT(m.at("lateral_pressure_ratio_K"), 0.6);
  EXPECT_LT(m.at("lateral_pressure_ratio_K"), 1.2);
  EXPECT_LT(m.at("screening_p/(K gamma z)"), 1.05);
  EXPECT_GT(m.at("effective_wall_friction_mu_w"), 0.0);
  // Frictionless grains: K, μ_w, the screening and the EN 1991-4 ratio are reported, with the reason;
  // the weight balance is judged against the bound the stop tests guarantee.
  for (const auto& r : v.rows) {
    if (r.quantity == "lateral_pressure_ratio_K" || r.quantity == "effective_wall_friction_mu_w" ||
        r.quantity == "en1991_4_p_hf_ratio" || r.quantity == "screening_p/(K gamma z)") {
      EXPECT_TRUE(harness::is_frictionless_report(r)) << r.quantity << ": " << r.reason;
    }
    if (r.quantity == "wall_load/weight") {
      EXPECT_EQ(r.verdict(), "pass") << r.reason;
      EXPECT_NEAR(r.tolerance, 0.01, 1e-15);  // p_ft of the case
    }
  }
  expect_all_pass(v);
}

TEST(Cases, ChungOoiNormalImpact) {
  const auto v = run("chung_ooi_normal_impact");
  const auto n = count_by_quantity(v);
  for (const char* q : {"hertz_max_overlap", "hertz_duration", "hertz_max_force", "normal_restitution"})
    EXPECT_EQ(n.at(q), 4u) << q;  // tests 1 (glass, limestone) and 2 (aluminium, magnesium)
  for (const char* q : {"hertz_max_overlap", "hertz_duration", "normal_restitution"})
    EXPECT_EQ(kinds(v, q), std::set<std::string>{"match"}) << q;
  EXPECT_EQ(kinds(v, "hertz_max_force"), std::set<std::string>{"report"});  // follows from the overlap
  expect_all_pass(v);
}

TEST(Cases, ChungOoiObliqueImpact) {
  const auto v = run("chung_ooi_oblique_impact");
  const auto n = count_by_quantity(v);
  EXPECT_EQ(n.at("normal_restitution"), 9u);
  EXPECT_EQ(n.at("rebound_spin"), 9u);
  // 40-85 deg slide throughout and are judged; 10-30 deg stick in part and are reported.
  std::size_t judged = 0, reported = 0;
  for (const auto& r : v.rows)
    if (r.quantity == "rebound_spin") (r.kind == harness::RowKind::Match ? judged : reported)++;
  EXPECT_EQ(judged, 6u);
  EXPECT_EQ(reported, 3u);
  expect_all_pass(v);
}

TEST(Cases, SlipToRoll) {
  const auto v = run("slip_to_roll");
  const auto n = count_by_quantity(v);
  EXPECT_EQ(n.at("sliding_speed"), 4u);  // mu 0.2, 0.5, 1 and the floor set moving (mu 0.5)
  EXPECT_EQ(n.at("rolling_speed"), 4u);
  EXPECT_EQ(kinds(v, "rolling_spin"), std::set<std::string>{"match"});
  expect_all_pass(v);
}

TEST(Cases, RollingResistance) {
  // A rolling ball against the constant torque and the EPSD spring (both limits): speed and spin
  // against (5/7)(g_t − μ_r g_n R*/r) thrown and on a slope, and the held ball's displacement bound.
  const auto v = run("rolling_resistance");
  const auto n = count_by_quantity(v);
  EXPECT_EQ(n.at("rolling_speed"), 7u);
  EXPECT_EQ(n.at("rolling_spin"), 7u);
  EXPECT_EQ(kinds(v, "held_displacement"), std::set<std::string>{"bound"});
  EXPECT_EQ(n.at("held_displacement"), 3u);
  expect_all_pass(v);
  // Undamped, the thrown ball's spin samples the tangential spring's swing (theory.md 10.5), which the
  // tolerance adds to the 1e-3: slip (F_s/k_t) sqrt(3.5 k_t/m), F_s = m a, k_t = 2/7 k_n, 2.5/3.5 of it in w r.
  const double r = 0.005, m = 2500 * 4.0 / 3.0 * std::numbers::pi * r * r * r, k_t = 2.0 / 7.0 * 1e5;
  const double r_star = r * 1000 / (1000 + r), a = 5.0 / 7.0 * 0.05 * 9.81 * r_star / r;
  const double slip = m * a / k_t * std::sqrt(3.5 * k_t / m);
  std::size_t swinging = 0;
  for (const auto& r_ : v.rows)
    if (r_.variant == "run=epsd_decay_undamped" && r_.quantity == "rolling_spin") {
      EXPECT_NEAR(r_.tolerance, 1e-3 + 2.5 / 3.5 * slip / std::abs(r_.expected * r), 1e-9);
      EXPECT_NE(r_.tolerance_source.find("swing"), std::string::npos);
      ++swinging;
    }
  EXPECT_EQ(swinging, 1u);
}

TEST(Cases, RollingResistanceReportsABallThatDoesNotStartRolling) {
  // Thrown without its spin, the ball first slides: the check's closed forms start rolling, so its
  // rows are reports with that reason, not verdicts.
  std::ifstream in(fs::path(SILODEM_SOURCE_DIR) / "cases" / "rolling_resistance.json");
  nlohmann::json c = nlohmann::json::parse(in);
  nlohmann::json run = c["verify"]["variants"]["run"]["cdt_decay"];
  run["balls"][0].erase("angular_velocity");
  c["verify"]["variants"] = {{"run", {{"sliding_start", run}}}};
  const fs::path dir = test_scratch::with_case("silodem_test_rolling_sliding", "case.json", c);
  harness::VerifyOptions opt;
  opt.out_root = dir / "out";
  opt.progress = false;
  const auto v = harness::verify_cases({dir / "case.json"}, opt);
  std::size_t reported = 0;
  for (const auto& r : v.rows)
    if (r.quantity == "rolling_speed" || r.quantity == "rolling_spin") {
      EXPECT_EQ(r.verdict(), "report");
      EXPECT_NE(r.reason.find("does not start rolling"), std::string::npos);
      ++reported;
    }
  EXPECT_EQ(reported, 2u);
}

TEST(Cases, FrictionalBed) {
  // Frictional grains (μ = 0.5, history spring; and with an EPSD rolling spring) at rest on a
  // floor of wall balls, the only wall: the floor carries the weight within p_ft = 1e-4, the bound
  // of the global stop test (28).
  const auto v = run("frictional_bed");
  // The weight from the case file itself: g Σ ρ 4/3 π r³ over its grains.
  std::ifstream in(fs::path(SILODEM_SOURCE_DIR) / "cases" / "frictional_bed.json");
  const nlohmann::json c = nlohmann::json::parse(in);
  const double rho = c["materials"]["grain"]["density"].get<double>(), g = -c["gravity"][2].get<double>();
  double weight = 0.0;
  for (const auto& b : c["balls"]) weight += rho * 4.0 / 3.0 * M_PI * std::pow(b["radius"].get<double>(), 3) * g;
  std::size_t rows = 0;
  for (const auto& r : v.rows)
    if (r.quantity == "wall_load/weight") {
      ++rows;
      EXPECT_EQ(r.kind, harness::RowKind::Match) << r.reason;  // a match only when the run stopped at rest
      EXPECT_NEAR(r.tolerance, 1e-4, 1e-18);                   // p_ft of the case
      EXPECT_NEAR(r.expected, weight, 1e-12 * weight);
      EXPECT_LE(std::abs(r.measured - weight), 1e-4 * weight);
    }
  EXPECT_EQ(rows, 2u);  // without rolling resistance, and with the EPSD rolling spring
  expect_all_pass(v);
}
