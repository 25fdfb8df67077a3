#pragma once
// Who runs a sweep's jobs (sweep/job_plan.hpp): this process one after another, this machine's
// cores as child processes, or a Slurm cluster as a job array. Every executor runs the same
// `silodem job PLAN K`, so the result files are the same whichever ran them.
#include <memory>
#include <string>
#include <vector>

#include "harness/sweep/job_plan.hpp"
#include "silodem/core/progress.hpp"

namespace harness {

class SweepExecutor {
 public:
  virtual ~SweepExecutor() = default;
  virtual std::string name() const = 0;
  /// Runs the listed jobs of the plan and returns when all have ended (each leaves its status file).
  virtual void run(const SweepPlan& plan, const std::vector<std::size_t>& jobs) = 0;
  /// The sweep's progress line (sweep/sweep_progress.hpp); off unless set.
  void set_progress(silodem::ProgressStyle style) { progress_ = style; }

 protected:
  silodem::ProgressStyle progress_;
};

/// In this process, one job after another (the library's default: no binary needed).
std::unique_ptr<SweepExecutor> in_process_executor();

/// Up to `parallel` child processes `silodem job PLAN K --threads T` at a time on this machine.
std::unique_ptr<SweepExecutor> local_executor(std::string silodem_binary, int parallel, int threads_per_job);

struct SlurmOptions {
  std::vector<std::string> sbatch_args;  // passed to sbatch as given: --partition, --account, --time, ...
  int threads_per_job = 1;               // --cpus-per-task and the job's --threads
  double poll_seconds = 2.0;
};

/// One `sbatch --array` of the jobs (the plan's folder must be on a file system every node shares);
/// waits until squeue no longer lists the array. A job that Slurm killed (time limit, node failure)
/// has no status file: job_failure says so with its log's tail.
std::unique_ptr<SweepExecutor> slurm_executor(std::string silodem_binary, SlurmOptions options);

}  // namespace harness
