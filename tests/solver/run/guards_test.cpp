// Run guards (run/guards.hpp): a run that goes wrong stops with a RunError naming the ball or
// pair, the step and the likely cause, leaves its last state in DIR.failed (never DIR), and a
// run within its limits is not disturbed.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
#include <algorithm>
#include <cctype>
#include <cmath>

#include "silodem/case/case_loader.hpp"
#include "silodem/run/guards.hpp"
#include "silodem/run/simulation.hpp"
#include "silodem/scene/scene_builder.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json two_balls(double speed, double duration, const json& guards = json::object()) {
  json c = {{"name", "guards"},
            {"seed", 1},
            {"gravity", {0.0, 0.0, 0.0}},
            {"materials", {{"g", {{"density", 2500}, {"stiffness", 1e5}, {"damping", 0.0}}}}},
            {"balls",
             {{{"id", "left"}, {"material", "g"}, {"radius", 0.005}, {"position", {-0.006, 0.0, 0.0}}, {"velocity", {speed, 0.0, 0.0}}},
              {{"id", "right"}, {"material", "g"}, {"radius", 0.005}, {"position", {0.006, 0.0, 0.0}}, {"velocity", {-speed, 0.0, 0.0}}}}},
            {"integrator", {{"scheme", "velocity_verlet"}}},
            {"time", {{"dt", 1e-6}, {"duration", duration}}}};
  if (!guards.empty()) c["guards"] = guards;
  return c;
}

std::string run_error(const json& c, const fs::path& out) {
  fs::remove_all(out);
  fs::remove_all(out.string() + ".failed");
  try {
    silodem::run_case(silodem::load_case(c), {out, false, false});
  } catch (const silodem::RunError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(RunGuards, AnImpactTooFastForTheStiffnessStopsAtTheOverlapGuard) {
  // Closing at 40 m/s, pair k = 5e4 N/m, m_eff = 6.5e-4 kg: the overlap would reach 0.9 r.
  const fs::path out = fs::temp_directory_path() / "silodem_guard_overlap";
  const std::string what = run_error(two_balls(20.0, 1e-3), out);
  EXPECT_NE(what.find("overlaps"), std::string::npos) << what;
  EXPECT_NE(what.find("\"right\""), std::string::npos) << what;
  EXPECT_NE(what.find("contact time"), std::string::npos) << what;
  EXPECT_FALSE(fs::exists(out));                                  // nothing that looks complete
  EXPECT_TRUE(fs::exists(out.string() + ".failed/state.json"));  // the last state, for inspection
  const json s = json::parse(std::ifstream(out.string() + ".failed/summary.json"));
  EXPECT_EQ(s["status"], "failed");
}

TEST(RunGuards, ABallLeavingTheDomainStopsTheRun) {
  json c = two_balls(0.0, 0.2, {{"domain_margin", 0.1}});
  c["balls"][0]["velocity"] = {0.0, 0.0, 5.0};  // 1 m in the run: past the 0.1 m margin
  const std::string what = run_error(c, fs::temp_directory_path() / "silodem_guard_domain");
  EXPECT_NE(what.find("\"left\""), std::string::npos) << what;
  EXPECT_NE(what.find("left the domain"), std::string::npos) << what;
}

TEST(RunGuards, StepLimitStopsARunAndAGentleRunPasses) {
  const std::string what = run_error(two_balls(0.1, 1e-3, {{"max_steps", 100}}), fs::temp_directory_path() / "silodem_guard_steps");
  EXPECT_NE(what.find("max_steps"), std::string::npos) << what;
  EXPECT_NE(what.find("step 100"), std::string::npos) << what;
  // The same collision at 0.1 m/s, no limit: no guard trips.
  EXPECT_EQ(run_error(two_balls(0.1, 1e-3), fs::temp_directory_path() / "silodem_guard_ok"), "");
}

namespace {

/// Whether a result file holds a word that stands for a number that is not one: nan, inf,
/// infinity (as C++ streams and printf write them) or null (as nlohmann::json writes NaN).
bool holds_non_finite(const fs::path& file) {
  std::ifstream in(file);
  std::string word;
  for (char ch; in.get(ch);) {
    if (std::isalpha(static_cast<unsigned char>(ch))) {
      word += char(std::tolower(static_cast<unsigned char>(ch)));
      continue;
    }
    if (word == "nan" || word == "inf" || word == "infinity" || word == "null") return true;
    word.clear();
  }
  return word == "nan" || word == "inf" || word == "infinity" || word == "null";
}

std::string guard_error(const silodem::RunGuards& guards, const silodem::Particles& p, const silodem::NeighbourList& list,
                        const silodem::EnergyState& ledger) {
  try {
    guards.check(p, list, silodem::ForceTotals{}, ledger, 1, 1e-6);
  } catch (const silodem::RunError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(RunGuards, EnergyDriftGuardTripsOnceTheLedgerHasExceededItFor101Steps) {
  // The oracle is the unguarded run's own ledger, every step in series.csv: the guard must trip
  // at the first step after the first 100 where |rel_drift| has exceeded the limit on 101 steps in
  // a row (that step and the 100 before), not before.
  json c = two_balls(1.0, 2e-3);
  c["integrator"] = {{"scheme", "predictor_corrector"}};  // explicit: a visible O(Δt) drift
  const fs::path out = fs::temp_directory_path() / "silodem_guard_drift";
  ASSERT_EQ(run_error(c, out), "");
  std::ifstream series(out / "series.csv");
  std::string line;
  std::getline(series, line);
  std::vector<double> drift;  // index = step
  while (std::getline(series, line)) {
    std::stringstream row(line);
    std::string cell;
    for (int col = 0; col <= 8; ++col) std::getline(row, cell, ',');  // column 8: rel_drift
    drift.push_back(std::abs(std::stod(cell)));
  }
  ASSERT_EQ(drift.size(), 2001u);
  const double peak = *std::max_element(drift.begin() + 101, drift.end());
  ASSERT_GT(peak, 1e-5);
  const double limit = 0.5 * peak;
  std::size_t first = 101, run = 0;
  for (std::size_t step = 1; step < drift.size(); ++step) {
    run = drift[step] > limit ? run + 1 : 0;
    if (step > 100 && run > 100) {
      first = step;
      break;
    }
  }
  ASSERT_GT(run, 100u) << "the drift never stays beyond the limit for 101 steps";
  c["guards"] = {{"max_energy_drift", limit}};
  const std::string what = run_error(c, out);
  EXPECT_NE(what.find("energy ledger no longer balances"), std::string::npos) << what;
  EXPECT_NE(what.find("at step " + std::to_string(first) + ","), std::string::npos) << "expected step " << first << ": " << what;
}

TEST(RunGuards, WallClockLimitStopsTheRunAtTheNext64thStep) {
  // Tested every 64 steps: with a limit of 1 ns the first test, at step 64, trips.
  const std::string what = run_error(two_balls(0.1, 1e-3, {{"max_wall_seconds", 1e-9}}),
                                     fs::temp_directory_path() / "silodem_guard_wall");
  EXPECT_NE(what.find("max_wall_seconds"), std::string::npos) << what;
  EXPECT_NE(what.find("at step 64,"), std::string::npos) << what;
  // A limit the run stays within does not disturb it.
  EXPECT_EQ(run_error(two_balls(0.1, 1e-3, {{"max_wall_seconds", 1e6}}), fs::temp_directory_path() / "silodem_guard_wall"), "");
}

TEST(RunGuards, TwoBallsMeetingAtOneCentreStopTheRunWithoutWritingANonFiniteState) {
  // Exact arithmetic: dt = 2^-16 s, speeds ±128 m/s, so each ball moves 2^-9 m per step, and
  // from ∓2^-8 m both reach x = 0 at step 2 without having touched (at step 1 they are 3 r apart).
  // The contact normal is then 0/0 and the forces NaN.
  const double r = 0x1p-9 / 1.5;
  json c = {{"name", "one_centre"},
            {"gravity", {0.0, 0.0, 0.0}},
            {"materials", {{"g", {{"density", 2500}, {"stiffness", 1.0}, {"damping", 0.0}}}}},
            {"balls",
             {{{"id", "left"}, {"material", "g"}, {"radius", r}, {"position", {-0x1p-8, 0.0, 0.0}}, {"velocity", {128.0, 0.0, 0.0}}},
              {{"id", "right"}, {"material", "g"}, {"radius", r}, {"position", {0x1p-8, 0.0, 0.0}}, {"velocity", {-128.0, 0.0, 0.0}}}}},
            {"integrator", {{"scheme", "velocity_verlet"}}},
            {"guards", {{"max_travel_ratio", 2.0}, {"max_overlap_ratio", 2.0}}},  // 1.5 r per step is allowed
            {"time", {{"dt", 0x1p-16}, {"duration", 100 * 0x1p-16}}}};
  const fs::path out = fs::temp_directory_path() / "silodem_guard_nonfinite";
  const std::string what = run_error(c, out);
  EXPECT_NE(what.find("non-finite contact force"), std::string::npos) << what;
  EXPECT_NE(what.find("same centre as ball"), std::string::npos) << what;
  EXPECT_NE(what.find("at step 2,"), std::string::npos) << what;
  EXPECT_NE(what.find("no state written"), std::string::npos) << what;
  const fs::path failed = out.string() + ".failed";
  EXPECT_FALSE(fs::exists(failed / "state.json"));  // its velocities are NaN
  const json s = json::parse(std::ifstream(failed / "summary.json"));
  EXPECT_EQ(s["status"], "failed");
  EXPECT_TRUE(s.contains("state_omitted"));
  EXPECT_FALSE(s["files"].contains("state"));
  for (const char* f : {"summary.json", "series.csv"}) EXPECT_FALSE(holds_non_finite(failed / f)) << f;
  std::ifstream series(failed / "series.csv");
  std::string line;
  int rows = -1;  // the header
  while (std::getline(series, line)) ++rows;
  EXPECT_EQ(rows, 2);  // t = 0 and step 1: the step that went non-finite is not written
}

TEST(RunGuards, ABallTooFastForTheTimeStepStopsBeforeItCanPassThroughABall) {
  // Falling at g = 1e6 m/s² from 10 m onto a fixed ball of 5.1 mm, dt = 5 µs: the guard allows
  // 0.5 r / dt = 510 m/s; velocity Verlet under constant gravity gives v = n g dt = 5n m/s after
  // step n, so it trips at step 103 (515 m/s), 13 cm into the fall and nearly 10 m above the
  // target, and names the time step 0.5 r / v that would resolve this speed.
  json c = {{"name", "tunnel"},
            {"gravity", {0.0, 0.0, -1e6}},
            {"materials", {{"g", {{"density", 2500}, {"stiffness", 1e5}, {"damping", 0.0}}}}},
            {"balls",
             {{{"id", "bullet"}, {"material", "g"}, {"radius", 0.0051}, {"position", {0.0, 0.0, 10.0}}},
              {{"id", "target"}, {"material", "g"}, {"radius", 0.0051}, {"position", {0.0, 0.0, 0.0}}, {"fixed", true}}}},
            {"integrator", {{"scheme", "velocity_verlet"}}},
            {"time", {{"dt", 5e-6}, {"duration", 0.01}}}};
  const fs::path out = fs::temp_directory_path() / "silodem_guard_travel";
  const std::string what = run_error(c, out);
  EXPECT_NE(what.find("ball \"bullet\""), std::string::npos) << what;
  EXPECT_NE(what.find("at 515 m/s"), std::string::npos) << what;
  EXPECT_NE(what.find("max_travel_ratio"), std::string::npos) << what;
  EXPECT_NE(what.find("at most 4.951e-06 s"), std::string::npos) << what;  // 0.5 · 0.0051 / 515
  EXPECT_NE(what.find("at step 103,"), std::string::npos) << what;
  const json state = json::parse(std::ifstream(out.string() + ".failed/state.json"));
  EXPECT_NEAR(state["balls"][0]["position"][2].get<double>(), 10.0 - 0.5e6 * std::pow(103 * 5e-6, 2), 1e-9);
}

TEST(RunGuards, EachNonFiniteQuantityIsNamed) {
  // The guard alone on a hand-made state: whichever quantity is not finite is the one named.
  const silodem::CaseConfig cfg = silodem::load_case(two_balls(1.0, 1e-3));
  silodem::Particles p = silodem::build_scene(cfg).particles;
  silodem::NeighbourList list(0.001, 0.0);
  list.build(p);
  const silodem::RunGuards guards(cfg, p);
  silodem::EnergyState ledger;
  EXPECT_EQ(guard_error(guards, p, list, ledger), "");
  p.v[1].y() = NAN;
  std::string what = guard_error(guards, p, list, ledger);
  EXPECT_NE(what.find("ball \"right\" at (0.006, 0, 0) m, v = (not finite) m/s has a non-finite velocity"), std::string::npos) << what;
  p.f[1].z() = INFINITY;
  EXPECT_NE(guard_error(guards, p, list, ledger).find("\"right\" at (0.006, 0, 0) m, v = (not finite) m/s has a non-finite contact force"),
            std::string::npos);
  p.x[1].x() = NAN;
  EXPECT_NE(guard_error(guards, p, list, ledger).find("\"right\" at (not finite) m, v = (not finite) m/s has a non-finite position"),
            std::string::npos);
  p = silodem::build_scene(cfg).particles;
  ledger.elastic = INFINITY;
  what = guard_error(guards, p, list, ledger);
  EXPECT_NE(what.find("the elastic energy is not finite at step 1"), std::string::npos) << what;
  EXPECT_EQ(what.find("inf"), std::string::npos) << what;  // the value itself is not printed
}
