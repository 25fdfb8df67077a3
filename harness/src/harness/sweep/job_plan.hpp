#pragma once
// A sweep as a plan of independent jobs (docs/cluster.md): each job is one run into its own result
// folder — a verify variant, or for compare a shared state, one code's run of a variant, or a
// seed-scatter run. The plan is a file a user can read (plan.json in the sweep
// folder); `silodem job PLAN K` runs job K, on this machine or on a cluster node, and leaves a
// status file beside the plan, so any executor (sweep/executor.hpp) can run the same jobs.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace silodem { struct CaseConfig; }

namespace harness {

struct SweepJob {
  std::filesystem::path case_file;  // absolute
  std::string case_name, variant;   // the variant's label as verify (or compare) prints it
  std::filesystem::path out_dir;    // absolute: the run's result folder
  // compare's jobs: "state" (silodem to the shared state; seed < 0 the case's own, else seeds[seed]),
  // "run" (`code` runs the variant), "seed_run" (silodem with seeds[seed], the variant); verify: "verify".
  std::string kind = "verify", code = "silodem";
  int seed = -1;
  std::filesystem::path from_state;  // compare's runs: the state.sds they continue from ("" for none)
  // compare's jobs: what the run depends on (the case file's digest, the job's fields, the ranks);
  // a done job's status file repeats it, and a resumed compare keeps the job only if both agree.
  nlohmann::json inputs;
  // What the run will cost, for the order a local sweep starts its jobs in (longest_first); not a
  // limit and not part of the result. 0: unknown (such jobs start last, in plan order).
  double expected_work = 0.0;
};

struct SweepPlan {
  std::filesystem::path dir;  // the sweep folder: plan.json, jobs/<k>.log, jobs/<k>.status.json
  std::vector<SweepJob> jobs;
  int ranks = 1;                     // compare: the reference codes' MPI ranks and launcher
  std::string launcher = "mpirun";
  std::filesystem::path file() const { return dir / "plan.json"; }
  std::filesystem::path log(std::size_t k) const;
  std::filesystem::path status(std::size_t k) const;
};

/// A run's expected cost in silodem ball-steps: its balls (with those a fill will drop) times its steps,
/// times the code's slowness against silodem's on the dense bed (reports/bench_dense.md, one core,
/// rounded: LAMMPS and LIGGGHTS 2, YADE 10). Only an ordering key.
double expected_work(const silodem::CaseConfig& cfg, const std::string& code);

/// The jobs in the order a sweep with a few workers should start them: the most expected work first
/// (a long run started last would run alone at the end), ties and unknowns in plan order.
std::vector<std::size_t> longest_first(const SweepPlan& plan, std::vector<std::size_t> jobs);

/// Writes plan.json (and creates the jobs folder); the file lists, per job, the command that runs it.
void write_plan(const SweepPlan& plan, const std::string& silodem_binary);
/// Reads plan.json; throws std::runtime_error naming the file and what is wrong.
SweepPlan read_plan(const std::filesystem::path& file);

/// Runs job k in this process with the given threads: the variant exactly as verify prepares it,
/// into its folder, then the status file ({"state": "done"} or {"state": "failed", "reason"}).
/// Returns false (status failed) instead of throwing for a failed run.
/// `progress_every`: the run's progress line (RunOptions::progress_every; < 0: none).
bool run_job(const SweepPlan& plan, std::size_t k, double progress_every = -1.0);

/// A job's outcome after an executor ran it: nullopt when it is done, else why not (the status
/// file's reason, or that there is none: killed, timed out, or never started), with the log's tail.
std::optional<std::string> job_failure(const SweepPlan& plan, std::size_t k);

/// Whether job k's folder already holds a complete result that verifies against its manifest and
/// was run from the same case input, its judging aside (run_inputs.hpp): a resumed sweep does not run
/// it again.
bool job_complete(const SweepPlan& plan, std::size_t k);

/// The same for one of compare's jobs: its status file says done, from the inputs the job has now
/// (SweepJob::inputs: the case as its runs read it), and its folder holds a complete result that
/// verifies against its manifest. A status recorded with the whole file's digest (before run digests)
/// counts if the file is unchanged, and is recorded again with the run digest.
bool compare_job_complete(const SweepPlan& plan, std::size_t k);

}  // namespace harness
