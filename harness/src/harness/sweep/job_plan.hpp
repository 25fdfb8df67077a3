#pragma once
// A sweep as a plan of independent jobs (docs/cluster.md): each job is one case variant run by
// silodem into its own result folder. The plan is a file a user can read (plan.json in the sweep
// folder); `silodem job PLAN K` runs job K, on this machine or on a cluster node, and leaves a
// status file beside the plan, so any executor (sweep/executor.hpp) can run the same jobs.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace harness {

struct SweepJob {
  std::filesystem::path case_file;  // absolute
  std::string case_name, variant;   // the variant's label as verify prints it
  std::filesystem::path out_dir;    // absolute: the run's result folder
};

struct SweepPlan {
  std::filesystem::path dir;  // the sweep folder: plan.json, jobs/<k>.log, jobs/<k>.status.json
  std::vector<SweepJob> jobs;
  std::filesystem::path file() const { return dir / "plan.json"; }
  std::filesystem::path log(std::size_t k) const;
  std::filesystem::path status(std::size_t k) const;
};

/// Writes plan.json (and creates the jobs folder); the file lists, per job, the command that runs it.
void write_plan(const SweepPlan& plan, const std::string& silodem_binary);
/// Reads plan.json; throws std::runtime_error naming the file and what is wrong.
SweepPlan read_plan(const std::filesystem::path& file);

/// Runs job k in this process with the given threads: the variant exactly as verify prepares it,
/// into its folder, then the status file ({"state": "done"} or {"state": "failed", "reason"}).
/// Returns false (status failed) instead of throwing for a failed run.
bool run_job(const SweepPlan& plan, std::size_t k);

/// A job's outcome after an executor ran it: nullopt when it is done, else why not (the status
/// file's reason, or that there is none: killed, timed out, or never started), with the log's tail.
std::optional<std::string> job_failure(const SweepPlan& plan, std::size_t k);

/// Whether job k's folder already holds a complete result that verifies against its manifest and
/// was run from the same case input: a resumed sweep does not run it again.
bool job_complete(const SweepPlan& plan, std::size_t k);

}  // namespace harness
