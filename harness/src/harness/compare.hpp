#pragma once
// `silodem compare`: one case file, every code. For each variant of the case's "compare" section
// and each code: run (or say why not), read the result files, apply the checks against theory,
// then compare every reference code with silodem quantity by quantity, hold silodem's own ledger
// against the rebuild from its dump, and lay the codes' energy ledgers side by side. The runs are
// the jobs of a plan (sweep/job_plan.hpp) in two rounds: the shared states, then the runs that
// continue from them; the section itself is read in compare_case.hpp.
#include <filesystem>
#include <functional>
#include <vector>

#include "harness/backends/backend.hpp"
#include "harness/sweep/job_plan.hpp"
#include "harness/verify.hpp"

namespace harness {

struct CompareOptions {
  std::filesystem::path out_root = "results/compare";
  std::vector<std::string> codes;  // empty: every code the case lists (default: all)
  bool progress = true;
  std::function<void()> before_first_run;  // once every input is checked (main prepares the outputs)
  Parallel parallel;  // MPI ranks and launcher of the codes that take them (LAMMPS, LIGGGHTS); others run on one
  /// Who runs the jobs (sweep/executor.hpp): null runs them in this process, one after another (the
  /// run times in the report are then each code alone on its core).
  SweepExecutor* executor = nullptr;
  std::string silodem_binary = "silodem";  // named in the plan's commands
  /// Keep the jobs whose results are complete and were run from the same inputs
  /// (sweep/job_plan.hpp, compare_job_complete); run only the others.
  bool resume = false;
};

/// Validates a case file's compare section, its variants and checks (tolerance sources, the dump
/// an energy_balance needs) without running anything; returns the number of compare variants
/// (0 for a case without a compare section). Throws silodem::CaseError naming the JSON path.
std::size_t validate_comparison(const std::filesystem::path& case_file);

/// Runs one of compare's jobs (sweep/job_plan.hpp: "state", "run" or "seed_run") with the reference
/// codes on `parallel`; returns "" when it produced its result, else why not.
std::string run_compare_job(const SweepJob& job, const Parallel& parallel, double progress_every = -1.0);

/// Throws silodem::CaseError for bad input before anything runs.
VerifyOutcome compare_cases(const std::vector<std::filesystem::path>& case_files, const CompareOptions& opt);

}  // namespace harness
