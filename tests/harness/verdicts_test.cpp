// Verdicts count only what was judged (issue 26 §6): the three row kinds, a tolerance without a
// source reported instead of judged, the headline counting judged quantities per case and variant
// with their sub-rows beside them, report rows apart in the Markdown and verdicts.json, and
// exit status 1 when nothing was judged.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <tuple>

#include "harness/check_row.hpp"
#include "harness/checks.hpp"
#include "harness/tolerance_source.hpp"
#include "harness/verdict_counts.hpp"
#include "harness/verdict_report.hpp"
#include "silodem/case/case_error.hpp"

namespace fs = std::filesystem;
using harness::BoundSide;
using harness::CheckRow;
using harness::RowKind;
using nlohmann::json;

namespace {

CheckRow match(double error, double tolerance, std::string source = "scheme bound: test") {
  CheckRow r;
  r.case_name = "c";
  r.variant = "base";
  r.quantity = "q";
  r.kind = RowKind::Match;
  r.error = error;
  r.tolerance = tolerance;
  r.tolerance_source = std::move(source);
  harness::judge(r);
  return r;
}

CheckRow bound(double measured, BoundSide side, double limit) {
  CheckRow r;
  r.kind = RowKind::Bound;
  r.measured = measured;
  r.side = side;
  r.bound = limit;
  r.tolerance_source = "closed form: test";
  harness::judge(r);
  return r;
}

CheckRow row(const std::string& c, const std::string& variant, const std::string& q, RowKind kind, bool pass,
             const std::string& subject = "s") {
  CheckRow r;
  r.case_name = c;
  r.variant = variant;
  r.quantity = q;
  r.subject = subject;
  r.kind = kind;
  r.pass = pass;
  if (kind == RowKind::Report) r.reason = "no oracle for " + q;
  else r.tolerance_source = "scheme bound: test";
  return r;
}

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST(RowKinds, MatchIsTwoSidedWithItsTolerance) {
  EXPECT_EQ(match(0.009, 0.01).verdict(), "pass");
  EXPECT_EQ(match(-0.009, 0.01).verdict(), "pass");
  EXPECT_EQ(match(0.011, 0.01).verdict(), "fail");
  EXPECT_EQ(match(-0.011, 0.01).verdict(), "fail");
  EXPECT_EQ(match(NAN, 0.01).verdict(), "fail");  // a missing measurement is a failure, not a pass
  EXPECT_TRUE(match(0.011, 0.01).judged());
}

TEST(RowKinds, BoundIsOneSidedAndGivesItsMargin) {
  EXPECT_EQ(bound(0.04, BoundSide::Upper, 0.05).verdict(), "pass");
  EXPECT_EQ(bound(-7.0, BoundSide::Upper, 0.05).verdict(), "pass");  // any distance below an upper bound
  EXPECT_EQ(bound(0.06, BoundSide::Upper, 0.05).verdict(), "fail");
  EXPECT_EQ(bound(0.96, BoundSide::Lower, 0.95).verdict(), "pass");
  EXPECT_EQ(bound(0.94, BoundSide::Lower, 0.95).verdict(), "fail");
  EXPECT_EQ(bound(NAN, BoundSide::Lower, 0.95).verdict(), "fail");
  EXPECT_NEAR(bound(0.94, BoundSide::Lower, 0.95).error, -0.01, 1e-15);
}

TEST(RowKinds, AReportRowNeverPassesOrFails) {
  CheckRow r = match(0.0, 0.01);
  ASSERT_EQ(r.verdict(), "pass");
  harness::to_report(r, "no oracle");
  EXPECT_EQ(r.verdict(), "report");
  EXPECT_FALSE(r.judged());
  EXPECT_FALSE(r.pass);
  // Whatever a caller sets afterwards, a report row is not counted as a pass — nor as a failure.
  r.pass = true;
  harness::judge(r);
  EXPECT_EQ(r.verdict(), "report");
  const auto h = harness::headline({r});
  EXPECT_EQ(h.total.judged, 0u);
  EXPECT_EQ(h.total.reported, 1u);
  EXPECT_FALSE(h.total.all_pass());
  CheckRow failing_report = match(5.0, 0.01);
  harness::to_report(failing_report, "no oracle");
  EXPECT_EQ(harness::headline({failing_report, match(0.0, 0.01)}).total.judged_passed, 1u);
  EXPECT_TRUE(harness::headline({failing_report, match(0.0, 0.01)}).total.all_pass());
}

TEST(RowKinds, ATolerancesWithoutSourceMakesTheRowAReport) {
  const CheckRow r = match(0.5, 0.01, "");  // would fail if judged
  EXPECT_EQ(r.kind, RowKind::Report);
  EXPECT_EQ(r.verdict(), "report");
  EXPECT_NE(r.reason.find("tolerance 0.01 has no stated source"), std::string::npos) << r.reason;
  CheckRow b;
  b.kind = RowKind::Bound;
  b.measured = 1.0;
  b.bound = 0.05;
  harness::judge(b);
  EXPECT_EQ(b.verdict(), "report");
  EXPECT_NE(b.reason.find("0.05"), std::string::npos) << b.reason;
  // A default row (nobody classified it) is a report row.
  EXPECT_EQ(CheckRow{}.verdict(), "report");
}

TEST(ToleranceSource, TheThreeSourcesAndTheirText) {
  const json spec = json::parse(R"j({
    "tolerance": 0.3, "tolerance_source": {"type": "seed_scatter", "realisations": 3, "scatter": 0.06, "measured": "run X"},
    "min_r2": 0.9, "min_r2_source": {"type": "published", "citation": "Landry et al., PRE 67, 041303 (2003)"},
    "max_scatter": 0.2, "max_scatter_source": {"type": "scheme_bound", "derivation": "5 blocks"}})j");
  const silodem::JsonReader r(spec, "$.verify.checks[2]");
  for (const char* k : {"tolerance", "min_r2", "max_scatter"}) EXPECT_NO_THROW(harness::validate_tolerance_source(r, k));
  EXPECT_EQ(harness::tolerance_source(spec, "tolerance", 0.3),
            "seed scatter 0.06 over 3 realisations (tolerance = 5 x scatter); measured: run X");
  EXPECT_EQ(harness::tolerance_source(spec, "min_r2", 0.9), "published: Landry et al., PRE 67, 041303 (2003)");
  EXPECT_EQ(harness::tolerance_source(spec, "max_scatter", 0.2), "scheme bound: 5 blocks");
  EXPECT_EQ(harness::tolerance_source(spec, "weight_tolerance", 0.02), "");
}

TEST(ToleranceSource, BadSourcesAreRefusedWithTheirJsonPath) {
  const auto refused = [](const char* text, const std::string& path_part) {
    const json spec = json::parse(text);
    try {
      harness::validate_tolerance_source(silodem::JsonReader(spec, "$.compare.between_codes[1]"), "tolerance");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const silodem::CaseError& e) {
      EXPECT_NE(e.path().find(path_part), std::string::npos) << e.path() << ": " << e.what();
    }
  };
  refused(R"({"tolerance_source": "seed scatter"})", "$.compare.between_codes[1].tolerance_source");
  refused(R"({"tolerance_source": {"type": "guess"}})", "tolerance_source.type");
  refused(R"({"tolerance_source": {"type": "seed_scatter", "realisations": 1, "scatter": 0.1}})", "realisations");
  refused(R"({"tolerance_source": {"type": "seed_scatter", "realisations": 3, "scatter": 0}})", "scatter");
  refused(R"({"tolerance_source": {"type": "published", "citation": "  "}})", "citation");
  refused(R"({"tolerance_source": {"type": "scheme_bound"}})", "derivation");
  refused(R"({"tolerance_source": {"type": "published", "citation": "x", "year": 1961}})", "year");
}

TEST(Headline, CountsJudgedQuantitiesPerCaseAndVariantWithSubRowsBeside) {
  std::vector<CheckRow> rows;
  // One case, two variants: 192 pairs of one quantity in each (one failing pair in the second).
  for (const char* v : {"dt=1", "dt=2"})
    for (int k = 0; k < 192; ++k)
      rows.push_back(row("collision", v, "restitution", RowKind::Match, !(std::string(v) == "dt=2" && k == 7)));
  rows.push_back(row("collision", "dt=1", "energy_drift", RowKind::Report, false));
  // A second case: a bound, 16 reported bands, a skipped run.
  rows.push_back(row("silo", "base", "wall_load/weight", RowKind::Bound, true));
  for (int b = 0; b < 16; ++b) rows.push_back(row("silo", "base", "band_pressure", RowKind::Report, false));
  CheckRow skip = row("silo", "base", "run", RowKind::Report, false);
  skip.skipped = true;
  rows.push_back(skip);
  for (auto& r : rows)
    if (r.kind == RowKind::Report) r.pass = true;  // even so: not a pass

  const auto h = harness::headline(rows);
  EXPECT_EQ(h.total.judged, 3u);         // restitution × 2 variants, wall load
  EXPECT_EQ(h.total.judged_passed, 2u);  // the second variant's restitution has a failing pair
  EXPECT_EQ(h.total.rows, 385u);
  EXPECT_EQ(h.total.rows_passed, 384u);
  EXPECT_EQ(h.total.reported, 2u);
  EXPECT_EQ(h.total.report_rows, 17u);
  EXPECT_EQ(h.total.skipped_rows, 1u);
  EXPECT_EQ(h.total.variants, 3u);
  EXPECT_FALSE(h.total.all_pass());
  ASSERT_EQ(h.cases.size(), 2u);
  EXPECT_EQ(h.cases[0].first, "collision");
  EXPECT_EQ(h.cases[0].second.judged, 2u);
  EXPECT_EQ(h.cases[0].second.rows, 384u);
  EXPECT_EQ(h.cases[0].second.variants, 2u);
  EXPECT_EQ(h.cases[1].second.judged, 1u);
  EXPECT_EQ(h.cases[1].second.judged_passed, 1u);
  EXPECT_EQ(h.cases[1].second.reported, 1u);
  EXPECT_EQ(harness::headline_sentence(h.total),
            "2 of 3 judged quantities passed (384 of 385 judged sub-rows); 2 quantities (17 rows) reported, not "
            "judged; 1 rows skipped");
}

TEST(Headline, NothingJudgedIsNotAPass) {
  harness::VerifyOutcome v;
  v.rows.push_back(row("c", "base", "band_pressure", RowKind::Report, true));
  CheckRow skip = row("c", "base", "run", RowKind::Report, false);
  skip.skipped = true;
  v.rows.push_back(skip);
  EXPECT_FALSE(v.all_pass());  // the subcommands exit 1
  v.rows.push_back(row("c", "base", "wall_load/weight", RowKind::Match, true));
  EXPECT_TRUE(v.all_pass());
  v.rows.push_back(harness::failed_run_row("c", "base", "lammps", "lammps failed: exit status 1"));
  EXPECT_FALSE(v.all_pass());
}

TEST(VerdictReport, MarkdownAndJsonListReportRowsApart) {
  harness::VerifyOutcome v;
  v.rows.push_back(row("silo", "base", "wall_load/weight", RowKind::Match, true, "all walls"));
  v.rows.back().tolerance = 0.01;
  v.rows.back().tolerance_source = "scheme bound p_ft: stop test";
  CheckRow k = row("silo", "base", "beverloo_k", RowKind::Report, false, "3 outlets");
  k.measured = 0.878;
  k.reason = harness::frictionless_reason("Beverloo's C and k");
  v.rows.push_back(k);
  const fs::path dir = fs::temp_directory_path() / "silodem_test_verdicts";
  fs::create_directories(dir);
  harness::write_verdict_markdown(dir / "report.md", v, "T", "P");
  const std::string md = read(dir / "report.md");
  const auto judged = md.find("## Judged"), reported = md.find("## Reported, not judged");
  ASSERT_NE(judged, std::string::npos);
  ASSERT_NE(reported, std::string::npos);
  ASSERT_LT(judged, reported);
  const std::string judged_part = md.substr(judged, reported - judged), report_part = md.substr(reported);
  EXPECT_NE(judged_part.find("| wall_load/weight | match |"), std::string::npos) << judged_part;
  EXPECT_EQ(judged_part.find("beverloo_k"), std::string::npos) << judged_part;
  EXPECT_NE(report_part.find("| beverloo_k | 3 outlets |"), std::string::npos) << report_part;
  EXPECT_NE(report_part.find("frictionless grains: Beverloo's C and k are published for frictional grains only"),
            std::string::npos)
      << report_part;
  EXPECT_NE(report_part.find("scheme bound p_ft: stop test"), std::string::npos);  // the judged row's source, listed
  EXPECT_NE(md.find("**ALL PASS**: 1 of 1 judged quantities passed (1 of 1 judged sub-rows); 1 quantities (1 rows) "
                    "reported, not judged"),
            std::string::npos)
      << md.substr(0, 400);
  EXPECT_NE(md.find("| silo | 1 | 1 / 1 | 1 / 1 | 1 (1) | 0 |"), std::string::npos);

  harness::write_verdict_json(dir / "verdicts.json", v);
  const json j = json::parse(read(dir / "verdicts.json"));
  EXPECT_TRUE(j.at("all_pass").get<bool>());
  EXPECT_EQ(j.at("headline").at("total").at("judged_quantities"), 1);
  EXPECT_EQ(j.at("headline").at("total").at("report_rows"), 1);
  EXPECT_EQ(j.at("headline").at("cases")[0].at("case"), "silo");
  EXPECT_EQ(j.at("rows")[0].at("kind"), "match");
  EXPECT_EQ(j.at("rows")[0].at("tolerance_source"), "scheme bound p_ft: stop test");
  EXPECT_EQ(j.at("rows")[1].at("kind"), "report");
  EXPECT_EQ(j.at("rows")[1].at("verdict"), "report");
  EXPECT_EQ(j.at("rows")[1].at("reason"), k.reason);
}

TEST(BeverlooFit, CAndKOfFrictionlessGrainsAreReportedAndTheFitNeedsASource) {
  std::vector<CheckRow> flows;
  const std::vector<std::string> variants{"D0=30", "D0=36", "D0=42"};
  const std::vector<double> outlets{0.030, 0.036, 0.042};
  // W = C ρ_b √g (D_0 − k d)^{5/2} with C = 0.58, k = 1.5, the frictional constants exactly.
  for (std::size_t i = 0; i < 3; ++i) {
    CheckRow w;
    w.variant = variants[i];
    w.quantity = "mass_flow_rate";
    w.measured = 0.58 * 1500.0 * std::sqrt(9.81) * std::pow(outlets[i] - 1.5 * 0.0055, 2.5);
    flows.push_back(w);
  }
  json spec = {{"grain_diameter", 0.0055}, {"bulk_density", 1500.0}, {"k_min", 1.3}, {"k_max", 2.9}, {"min_r2", 0.95}};
  auto rows = harness::beverloo_fit_rows(spec, "silo_discharge", flows, variants, outlets, 9.81, false);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_NEAR(rows[1].measured, 1.5, 1e-9);   // k recovered
  EXPECT_NEAR(rows[2].measured, 0.58, 1e-9);  // C recovered
  for (std::size_t i : {1u, 2u}) {
    EXPECT_EQ(rows[i].verdict(), "report") << rows[i].quantity;  // in range, and still not a pass
    EXPECT_TRUE(harness::is_frictionless_report(rows[i])) << rows[i].reason;
  }
  EXPECT_EQ(rows[0].verdict(), "report");  // min_r2 without a source
  spec["min_r2_source"] = {{"type", "published"}, {"citation", "Beverloo et al., Chem. Eng. Sci. 15 (1961) 260"}};
  rows = harness::beverloo_fit_rows(spec, "silo_discharge", flows, variants, outlets, 9.81, false);
  EXPECT_EQ(rows[0].kind, RowKind::Bound);
  EXPECT_EQ(rows[0].verdict(), "pass");
  EXPECT_NEAR(rows[0].measured, 1.0, 1e-12);
}

TEST(BeverlooFit, CAndKOfFrictionalGrainsAreJudgedWithinTheirPublishedRanges) {
  const std::vector<std::string> variants{"D0=30", "D0=38", "D0=47", "D0=55"};
  const std::vector<double> outlets{0.030, 0.0385, 0.047, 0.055};
  const json published = {{"type", "published"}, {"citation", "Beverloo et al. (1961); Nedderman et al. (1982)"}};
  const json spec = {{"grain_diameter", 0.0055}, {"bulk_density", 1500.0}, {"k_min", 1.3}, {"k_max", 2.9},
                     {"min_r2", 0.95}, {"C_range", {0.55, 0.65}}, {"C_range_source", published},
                     {"k_range", {1.3, 2.9}}, {"k_range_source", published}};
  // Flows of C = 0.6, k = 2 pass; C = 0.7 fails the C range, k = 1.0 fails the k range.
  for (const auto& [C, k, C_ok, k_ok] : std::vector<std::tuple<double, double, bool, bool>>{
           {0.6, 2.0, true, true}, {0.7, 2.0, false, true}, {0.6, 1.0, true, false}}) {
    std::vector<CheckRow> flows;
    for (std::size_t i = 0; i < outlets.size(); ++i) {
      CheckRow w;
      w.variant = variants[i];
      w.quantity = "mass_flow_rate";
      w.measured = C * 1500.0 * std::sqrt(9.81) * std::pow(outlets[i] - k * 0.0055, 2.5);
      flows.push_back(w);
    }
    const auto rows = harness::beverloo_fit_rows(spec, "silo", flows, variants, outlets, 9.81, true);
    EXPECT_NEAR(rows[1].measured, k, 1e-9);
    EXPECT_NEAR(rows[2].measured, C, 1e-9);
    EXPECT_EQ(rows[1].verdict(), k_ok ? "pass" : "fail") << "k " << k;
    EXPECT_EQ(rows[2].verdict(), C_ok ? "pass" : "fail") << "C " << C;
    EXPECT_NE(rows[2].tolerance_source.find("Nedderman"), std::string::npos);
  }
  // Without a range a frictional C is reported, saying the range is missing.
  json bare = spec;
  bare.erase("C_range");
  std::vector<CheckRow> flows;
  for (std::size_t i = 0; i < outlets.size(); ++i) {
    CheckRow w;
    w.variant = variants[i];
    w.quantity = "mass_flow_rate";
    w.measured = 0.6 * 1500.0 * std::sqrt(9.81) * std::pow(outlets[i] - 2.0 * 0.0055, 2.5);
    flows.push_back(w);
  }
  const auto rows = harness::beverloo_fit_rows(bare, "silo", flows, variants, outlets, 9.81, true);
  EXPECT_EQ(rows[2].verdict(), "report");
  EXPECT_NE(rows[2].reason.find("C_range"), std::string::npos);
}

#include "harness/compare.hpp"
#include "silodem/case/case_loader.hpp"

// A ledger rebuilt from dump frames cannot integrate the dashpot work of a contact that falls
// between frames (a 1000-step dump gave a drift of 1.71 in every code): energy_balance is refused
// before anything runs, naming the check; frames of every step resolve a contact by t_c/Δt.
TEST(EnergyBalance, RefusedAtLoadWhenTheDumpCannotResolveAContact) {
  std::ifstream in(fs::path(SILODEM_SOURCE_DIR) / "cases" / "collision_restitution.json");
  json c = json::parse(in);
  const silodem::CaseConfig every_step = silodem::load_case(c);
  // The shortest contact of the case lasts tens of steps of t_c/50 (the reference pair's t_c).
  EXPECT_GT(harness::energy_frames_per_contact(every_step), 20.0);
  EXPECT_LT(harness::energy_frames_per_contact(every_step), 51.0);
  c["compare"]["base"]["output"]["dump_interval_steps"] = 1000;
  const fs::path file = fs::temp_directory_path() / "silodem_test_sparse_dump.json";
  std::ofstream(file) << c.dump();
  harness::CompareOptions opt;
  opt.out_root = fs::temp_directory_path() / "silodem_test_sparse_dump_out";
  fs::remove_all(opt.out_root);  // the test's own scratch: a leftover of another build is not silodem's to keep
  opt.progress = false;
  fs::remove_all(opt.out_root);
  try {
    (void)harness::compare_cases({file}, opt);
    FAIL() << "a 1000-step dump was accepted for energy_balance";
  } catch (const silodem::CaseError& e) {
    const std::string what = e.what();
    EXPECT_NE(e.path().find("$.compare.checks[1]"), std::string::npos) << e.path();  // the energy_balance entry
    EXPECT_NE(what.find("dumps every 1000 steps cannot integrate the dashpot work"), std::string::npos) << what;
    EXPECT_NE(what.find("output.dump_interval_steps"), std::string::npos) << what;
  }
  EXPECT_FALSE(fs::exists(opt.out_root));  // refused before anything ran
}

// The case files as generated (cases/generators/) pass validation with their tolerance sources,
// verify and compare sections alike.
TEST(CaseFiles, EveryCaseValidatesWithItsToleranceSources) {
  std::size_t sourced = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(SILODEM_SOURCE_DIR) / "cases")) {
    if (entry.path().extension() != ".json") continue;
    EXPECT_GT(harness::validate_verification(entry.path()), 0u) << entry.path();
    EXPECT_NO_THROW((void)harness::validate_comparison(entry.path())) << entry.path();
    std::ifstream in(entry.path());
    const json c = json::parse(in);
    if (c.contains("compare"))
      for (const auto& b : c["compare"].value("between_codes", json::array())) sourced += b.contains("tolerance_source");
  }
  EXPECT_GT(sourced, 5u);  // the between-codes tolerances the generators could source
}

#include <sys/wait.h>

// The subcommand's exit status counts only judged rows: a verify run whose only check has a
// tolerance without a source judges nothing and exits 1; the same tolerance with its source is
// judged, passes, and exits 0.
TEST(ExitStatus, NothingJudgedExitsOne) {
  std::ifstream in(fs::path(SILODEM_SOURCE_DIR) / "cases" / "cohesion_cutoff.json");
  json c = json::parse(in);
  c.erase("compare");
  c["verify"] = {{"checks", json::array({{{"type", "energy_balance"}, {"tolerance", 1e-6}}})}};
  const fs::path dir = fs::temp_directory_path() / "silodem_test_exit_status";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto verify = [&](const json& cj, const std::string& tag) {
    std::ofstream(dir / (tag + ".json")) << cj.dump();
    const std::string cmd = std::string(SILODEM_BINARY) + " verify " + (dir / (tag + ".json")).string() + " --out " +
                            (dir / tag).string() + " --quiet >/dev/null 2>&1";
    const int s = std::system(cmd.c_str());
    return WIFEXITED(s) ? WEXITSTATUS(s) : -1;
  };
  EXPECT_EQ(verify(c, "unsourced"), 1);
  const json v = json::parse(read(dir / "unsourced" / "verdicts.json"));
  EXPECT_FALSE(v.at("all_pass").get<bool>());
  EXPECT_EQ(v.at("headline").at("total").at("judged_quantities"), 0);
  EXPECT_EQ(v.at("rows")[0].at("verdict"), "report");
  c["verify"]["checks"][0]["tolerance_source"] = {
      {"type", "scheme_bound"}, {"derivation", "no dashpot: the ledger closes to rounding (test only)"}};
  EXPECT_EQ(verify(c, "sourced"), 0);
  EXPECT_EQ(json::parse(read(dir / "sourced" / "verdicts.json")).at("rows")[0].at("verdict"), "pass");
}
