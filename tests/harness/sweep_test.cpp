// A verify sweep as a plan of jobs (harness/sweep/): the same two-variant case run in this process,
// as child processes on this machine and as a Slurm job array gives the same verdict rows and
// bitwise the same result files (a run's results depend only on its case); a job whose run fails is
// a failed row with its reason and log; --resume runs only what is missing or failed. The Slurm
// part needs a running Slurm (tools/slurm_local.sh start, SLURM_CONF exported; tools/test.sh does
// both): without one it is skipped with the reason, never replaced by a stand-in.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "harness/compare.hpp"
#include "harness/sweep/executor.hpp"
#include "harness/sweep/job_plan.hpp"
#include "harness/verify.hpp"
#include "silodem/case/case_loader.hpp"
#include "silodem/output/manifest.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

/// Each test its own scratch (ctest runs them side by side).
const fs::path kLocalScratch = fs::temp_directory_path() / "silodem_test_sweep_local";
const fs::path kSlurmScratch = fs::temp_directory_path() / "silodem_test_sweep_slurm";

/// collision_restitution at two steps with velocity Verlet: two jobs of a second or so.
fs::path two_variant_case(const fs::path& scratch) {
  std::ifstream in(fs::path(SILODEM_SOURCE_DIR) / "cases" / "collision_restitution.json");
  json c = json::parse(in);
  json dt = c["verify"]["variants"]["dt"];
  c["verify"]["variants"] = {{"dt", dt}};
  c["integrator"] = {{"scheme", "velocity_verlet"}};
  fs::create_directories(scratch);
  const fs::path file = scratch / "sweep_case.json";
  std::ofstream(file) << c.dump();
  return file;
}

harness::VerifyOutcome sweep(const fs::path& out, harness::SweepExecutor* executor, bool resume = false) {
  harness::VerifyOptions opt;
  opt.out_root = out;
  opt.progress = false;
  opt.executor = executor;
  opt.resume = resume;
  return harness::verify_cases({two_variant_case(out.parent_path())}, opt);
}

std::string file_text(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The rows without their run times, and every result file that depends only on the case.
void expect_same_sweep(const fs::path& a, const harness::VerifyOutcome& ra, const fs::path& b,
                       const harness::VerifyOutcome& rb) {
  ASSERT_EQ(ra.rows.size(), rb.rows.size());
  for (std::size_t i = 0; i < ra.rows.size(); ++i) {
    EXPECT_EQ(ra.rows[i].quantity, rb.rows[i].quantity);
    EXPECT_EQ(ra.rows[i].variant, rb.rows[i].variant);
    EXPECT_EQ(ra.rows[i].measured, rb.rows[i].measured) << ra.rows[i].quantity;  // bitwise
    EXPECT_EQ(ra.rows[i].pass, rb.rows[i].pass);
  }
  EXPECT_TRUE(ra.all_pass());
  int compared = 0;
  for (const auto& e : fs::recursive_directory_iterator(a / "collision_restitution")) {
    const std::string name = e.path().filename().string();
    if (name != "series.csv" && name != "state.json") continue;
    const fs::path other = b / fs::relative(e.path(), a);
    EXPECT_EQ(file_text(e.path()), file_text(other)) << other;
    ++compared;
  }
  EXPECT_EQ(compared, 4) << "two variants, each with its series and state";
}

}  // namespace

TEST(Sweep, ThisProcessAndChildProcessesGiveTheSameResultsAndAResumeRunsOnlyWhatFailed) {
  fs::remove_all(kLocalScratch);  // the test's own scratch
  const auto here = sweep(kLocalScratch / "in_process", nullptr);
  const auto local = harness::local_executor(SILODEM_BINARY, 2, 1);
  const auto children = sweep(kLocalScratch / "local", local.get());
  expect_same_sweep(kLocalScratch / "in_process", here, kLocalScratch / "local", children);
  const harness::SweepPlan plan = harness::read_plan(kLocalScratch / "local" / "sweep" / "plan.json");
  ASSERT_EQ(plan.jobs.size(), 2u);
  EXPECT_TRUE(harness::job_complete(plan, 0) && harness::job_complete(plan, 1));

  // Job 1's result damaged (it no longer verifies against its manifest) and job 0's folder made
  // unwritable-by-replacement: a plain file where the run must rename its folder.
  std::ofstream(plan.jobs[1].out_dir / "series.csv", std::ios::app) << "damaged\n";
  EXPECT_FALSE(harness::job_complete(plan, 1));
  fs::remove_all(plan.jobs[0].out_dir);
  std::ofstream(plan.jobs[0].out_dir) << "not silodem's\n";
  const auto failed = sweep(kLocalScratch / "local", local.get(), true);
  int failed_rows = 0;
  for (const auto& r : failed.rows)
    if (r.quantity == "run" && !r.pass) {
      ++failed_rows;
      EXPECT_EQ(r.variant, plan.jobs[0].variant);
      EXPECT_NE(r.note.find("log"), std::string::npos) << r.note;
    }
  EXPECT_EQ(failed_rows, 1);
  EXPECT_FALSE(failed.all_pass());
  EXPECT_TRUE(harness::job_complete(plan, 1)) << "the damaged result was run again";

  // The obstacle removed, a resume runs job 0 alone: job 1's result is kept as it is.
  fs::remove(plan.jobs[0].out_dir);
  const auto kept = fs::last_write_time(plan.jobs[1].out_dir / "manifest.json");
  const auto resumed = sweep(kLocalScratch / "local", local.get(), true);
  EXPECT_TRUE(resumed.all_pass());
  EXPECT_EQ(fs::last_write_time(plan.jobs[1].out_dir / "manifest.json"), kept);
  expect_same_sweep(kLocalScratch / "in_process", here, kLocalScratch / "local", resumed);

  // A check's tolerance edited: both runs still count (only the judging changed); the scene edited
  // (the run's duration): neither does.
  const fs::path file = plan.jobs[0].case_file;
  json c = json::parse(std::ifstream(file));
  c["verify"]["checks"].back()["tolerance"] = 0.06;
  std::ofstream(file) << c.dump();
  EXPECT_TRUE(harness::job_complete(plan, 0) && harness::job_complete(plan, 1));
  c["time"]["duration"] = 1.5 * c["time"]["duration"].get<double>();
  std::ofstream(file) << c.dump();
  EXPECT_FALSE(harness::job_complete(plan, 0) || harness::job_complete(plan, 1));
}

TEST(Sweep, ASlurmJobArrayGivesTheSameResultsAsThisMachine) {
  const char* conf = std::getenv("SLURM_CONF");
  if (!conf || std::system("sinfo -h > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "no running Slurm: " << (conf ? std::string("sinfo fails with SLURM_CONF=") + conf
                                                   : std::string("SLURM_CONF is not set"))
                 << " (tools/slurm_local.sh start starts a one-node cluster; tools/test.sh does)";
  fs::remove_all(kSlurmScratch);  // the test's own scratch
  const fs::path out = kSlurmScratch / "slurm_root";
  const auto local = harness::local_executor(SILODEM_BINARY, 2, 1);
  const auto reference = sweep(kSlurmScratch / "local_ref", local.get());
  harness::SlurmOptions so;
  so.poll_seconds = 0.5;
  const auto slurm = harness::slurm_executor(SILODEM_BINARY, so);
  const auto on_slurm = sweep(out, slurm.get());
  expect_same_sweep(kSlurmScratch / "local_ref", reference, out, on_slurm);
  EXPECT_NE(file_text(out / "sweep" / "sweep.sbatch").find("#SBATCH --array=0,1"), std::string::npos);
}

namespace {

/// A grain thrown at a steel cylinder (compare_test.cpp's smooth wall), continued from t = 0.2 ms,
/// with two more seeds: three shared states, then silodem's and LAMMPS's runs and two seed runs.
fs::path wall_throw_case(const fs::path& dir, const std::string& report = "a plumbing test", double duration = 0.0005) {
  json c = json::parse(R"({
    "format": "silodem-case/1", "name": "wall_throw", "gravity": [0, 0, 0],
    "contact": {"normal": "hertz", "tangential": "mindlin", "clamp_tensile_force": true},
    "materials": {"grain": {"density": 2500, "youngs_modulus": 1e9, "poisson_ratio": 0.2, "restitution": 0.5, "friction": 0.3},
                  "steel": {"density": 7200, "youngs_modulus": 2.1e11, "poisson_ratio": 0.2, "restitution": 0.6, "friction": 0.5}},
    "surfaces": [{"name": "silo", "material": "steel", "axis": [0, 0], "profile": [[0.05, 0.05], [0.05, -0.05]]}],
    "balls": [{"id": "g", "material": "grain", "radius": 0.002, "position": [0.045, 0.01, 0], "velocity": [1, 0.2, 0]}],
    "integrator": {"scheme": "velocity_verlet", "dashpot_velocity": "half_step"},
    "time": {"dt": 1e-7, "duration": 0.0005},
    "output": {"series_interval": 1e-4},
    "verify": {"checks": [{"type": "energy_balance", "tolerance": 0.05}]},
    "compare": {"from_state_at": 0.0002, "seeds": [5, 6], "checks": [{"type": "energy_terms"}],
                "between_codes": [{"quantity": "energy_kinetic", "report": "a plumbing test"}]}})");
  c["compare"]["between_codes"][0]["report"] = report;
  c["time"]["duration"] = duration;
  std::ofstream(dir / "wall_throw.json") << c.dump();
  return dir / "wall_throw.json";
}

}  // namespace

// compare's jobs come in two rounds: the shared states (the case's seed and each of compare.seeds),
// then every code's run and the seed-scatter runs, which continue from them. A grain thrown at a
// steel cylinder (compare_test.cpp's smooth wall), continued from t = 0.2 ms, in silodem and LAMMPS:
// this process and two child processes at a time give the same rows, and the plan lists the three
// states before the runs.
TEST(Sweep, CompareRunsItsSharedStatesFirstAndAnyExecutorGivesTheSameRows) {
  const fs::path dir = fs::temp_directory_path() / "silodem_test_sweep_compare";
  fs::remove_all(dir);  // the test's own scratch
  fs::create_directories(dir);
  wall_throw_case(dir);
  const auto run = [&](const std::string& label, harness::SweepExecutor* executor) {
    harness::CompareOptions opt;
    opt.out_root = dir / label;
    opt.progress = false;
    opt.codes = {"silodem", "lammps"};
    opt.executor = executor;
    return harness::compare_cases({dir / "wall_throw.json"}, opt);
  };
  const auto here = run("in_process", nullptr);
  const auto local = harness::local_executor(SILODEM_BINARY, 2, 1);
  const auto children = run("local", local.get());
  ASSERT_EQ(here.rows.size(), children.rows.size());
  int measured = 0;
  for (std::size_t i = 0; i < here.rows.size(); ++i) {
    EXPECT_EQ(here.rows[i].code, children.rows[i].code);
    EXPECT_EQ(here.rows[i].quantity, children.rows[i].quantity);
    if (here.rows[i].quantity == "energy_kinetic") {
      EXPECT_EQ(here.rows[i].measured, children.rows[i].measured) << here.rows[i].code;  // bitwise
      ++measured;
    }
  }
  EXPECT_GE(measured, 3) << "silodem, LAMMPS, and silodem against LAMMPS";
  const harness::SweepPlan plan = harness::read_plan(dir / "local" / "sweep" / "plan.json");
  ASSERT_EQ(plan.jobs.size(), 3u + 2u + 2u) << "3 states; silodem and LAMMPS; 2 seed runs";
  for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(plan.jobs[k].kind, "state");
  for (std::size_t k = 3; k < plan.jobs.size(); ++k) {
    EXPECT_NE(plan.jobs[k].kind, "state");
    EXPECT_FALSE(plan.jobs[k].from_state.empty());
  }
}

// A resumed compare (--resume) keeps every job that finished from the same inputs and runs only the
// rest: a LAMMPS run whose folder is gone runs again alone, with the same rows; a case whose judging
// alone changed keeps every run, one whose scene changed runs everything again; a status of an
// earlier build (the whole file's digest) counts while the file is unchanged.
TEST(Sweep, ACompareResumeRunsOnlyWhatIsMissingOrChanged) {
  const fs::path dir = fs::temp_directory_path() / "silodem_test_sweep_compare_resume";
  fs::remove_all(dir);  // the test's own scratch
  fs::create_directories(dir);
  const auto run = [&](bool resume, const std::string& report = "a plumbing test", double duration = 0.0005) {
    harness::CompareOptions opt;
    opt.out_root = dir / "out";
    opt.progress = false;
    opt.codes = {"silodem", "lammps"};
    opt.resume = resume;
    return harness::compare_cases({wall_throw_case(dir, report, duration)}, opt);
  };
  // The case's rows are reports (nothing judged); a failed run would be a judged failing "run" row.
  const auto no_failed_row = [](const harness::VerifyOutcome& o) {
    return !o.rows.empty() && std::none_of(o.rows.begin(), o.rows.end(), [](const auto& r) { return r.judged() && !r.pass; });
  };
  const auto first = run(false);
  ASSERT_TRUE(no_failed_row(first));
  const harness::SweepPlan plan = harness::read_plan(dir / "out" / "sweep" / "plan.json");
  ASSERT_EQ(plan.jobs.size(), 7u);
  std::size_t lammps = plan.jobs.size();
  std::vector<fs::file_time_type> written;
  for (std::size_t k = 0; k < plan.jobs.size(); ++k) {
    EXPECT_TRUE(harness::compare_job_complete(plan, k)) << k;
    written.push_back(fs::last_write_time(plan.jobs[k].out_dir / "manifest.json"));
    if (plan.jobs[k].code == "lammps") lammps = k;
  }
  ASSERT_LT(lammps, plan.jobs.size());

  fs::remove_all(plan.jobs[lammps].out_dir);
  EXPECT_FALSE(harness::compare_job_complete(plan, lammps));
  const auto resumed = run(true);
  ASSERT_EQ(resumed.rows.size(), first.rows.size());
  for (std::size_t i = 0; i < first.rows.size(); ++i) {
    EXPECT_EQ(resumed.rows[i].quantity, first.rows[i].quantity);
    const double a = resumed.rows[i].measured, b = first.rows[i].measured;  // bitwise, or both not measured
    EXPECT_TRUE(a == b || (std::isnan(a) && std::isnan(b))) << first.rows[i].code << " " << first.rows[i].quantity;
  }
  for (std::size_t k = 0; k < plan.jobs.size(); ++k) {
    const auto now = fs::last_write_time(plan.jobs[k].out_dir / "manifest.json");
    if (k == lammps) EXPECT_NE(now, written[k]) << "the missing run ran again";
    else EXPECT_EQ(now, written[k]) << "job " << k << " was kept";
  }

  // The judging changed (a between-codes row's text): every run is kept, and judged again.
  for (std::size_t k = 0; k < plan.jobs.size(); ++k) written[k] = fs::last_write_time(plan.jobs[k].out_dir / "manifest.json");
  const auto rejudged = run(true, "a plumbing test, judged again");
  EXPECT_TRUE(no_failed_row(rejudged));
  EXPECT_TRUE(std::any_of(rejudged.rows.begin(), rejudged.rows.end(),
                          [](const auto& r) { return r.reason.find("judged again") != std::string::npos; }));
  for (std::size_t k = 0; k < plan.jobs.size(); ++k)
    EXPECT_EQ(fs::last_write_time(plan.jobs[k].out_dir / "manifest.json"), written[k]) << "job " << k << " was kept";

  // A status of an earlier build recorded the whole file's digest: it counts while the file is
  // unchanged, and is recorded again with the run digest.
  const harness::SweepPlan now = harness::read_plan(dir / "out" / "sweep" / "plan.json");
  json legacy = now.jobs[lammps].inputs;
  legacy.erase("run_digest");
  legacy["case_digest"] = silodem::file_digest(now.jobs[lammps].case_file);
  std::ofstream(now.status(lammps)) << json{{"state", "done"}, {"inputs", legacy}}.dump();
  EXPECT_TRUE(harness::compare_job_complete(now, lammps));
  EXPECT_EQ(json::parse(std::ifstream(now.status(lammps))).at("inputs"), now.jobs[lammps].inputs);
  legacy["case_digest"] = "1:00000000";  // another file
  std::ofstream(now.status(lammps)) << json{{"state", "done"}, {"inputs", legacy}}.dump();
  EXPECT_FALSE(harness::compare_job_complete(now, lammps));
  std::ofstream(now.status(lammps)) << json{{"state", "done"}, {"inputs", now.jobs[lammps].inputs}}.dump();

  // The scene changed (the run's duration): nothing is kept.
  const auto changed = run(true, "a plumbing test, judged again", 0.0006);
  EXPECT_TRUE(no_failed_row(changed));
  for (std::size_t k = 0; k < plan.jobs.size(); ++k)
    EXPECT_NE(fs::last_write_time(plan.jobs[k].out_dir / "manifest.json"), written[k]) << "job " << k << " ran again";
}

// A local sweep starts the runs expected to take longest first, so a long run does not start last
// and run alone at the end: expected work is balls × steps × the code's slowness (job_plan.hpp).
TEST(Sweep, ALocalSweepStartsTheLongestExpectedRunsFirst) {
  std::ifstream in(fs::path(SILODEM_SOURCE_DIR) / "cases" / "collision_restitution.json");
  const silodem::CaseConfig cfg = silodem::load_case(json::parse(in));
  const double steps = cfg.duration / cfg.dt;
  ASSERT_GT(cfg.balls.size(), 0u);
  EXPECT_DOUBLE_EQ(harness::expected_work(cfg, "silodem"), double(cfg.balls.size()) * steps);
  EXPECT_DOUBLE_EQ(harness::expected_work(cfg, "yade"), 10.0 * harness::expected_work(cfg, "silodem"));
  silodem::CaseConfig longer = cfg;
  longer.duration *= 3.0;
  silodem::CaseConfig continued = longer;  // a continuation runs only the steps after its start
  continued.start_step = long(2.0 * steps);
  EXPECT_NEAR(harness::expected_work(continued, "silodem"), harness::expected_work(cfg, "silodem"), 1e-6 * steps);

  harness::SweepPlan plan;
  plan.jobs.resize(5);
  plan.jobs[0].expected_work = harness::expected_work(cfg, "silodem");
  plan.jobs[1].expected_work = 0.0;  // unknown: last
  plan.jobs[2].expected_work = harness::expected_work(longer, "silodem");
  plan.jobs[3].expected_work = harness::expected_work(cfg, "yade");
  plan.jobs[4].expected_work = harness::expected_work(cfg, "silodem");  // a tie with job 0 keeps plan order
  EXPECT_EQ(harness::longest_first(plan, {0, 1, 2, 3, 4}), (std::vector<std::size_t>{3, 2, 0, 4, 1}));
  EXPECT_EQ(harness::longest_first(plan, {4, 1, 0}), (std::vector<std::size_t>{4, 0, 1}));
}
