#pragma once
// One backend per code, each the only place that knows that code. A backend turns a validated
// case into result files (summary.json, series.csv, probes/) in a directory; the comparator reads
// only those files.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "silodem/case/case_config.hpp"

namespace harness {

struct BackendResult {
  enum class Status { Ran, NotFound, NotRepresentable, Failed };
  Status status = Status::Failed;
  std::string reason;  // why it did not run, or what went wrong (with the log tail)
  std::filesystem::path dir;
};

/// How a reference code is run in parallel: MPI ranks and the launcher that starts them.
struct Parallel {
  int ranks = 1;
  std::string launcher = "mpirun";  // "mpirun" (mpirun -np N) or "srun" (srun -n N, inside an allocation)
};

class Backend {
 public:
  virtual ~Backend() = default;
  virtual std::string code() const = 0;
  /// Why this code cannot represent the case ("" if it can).
  virtual std::string not_representable(const silodem::CaseConfig& cfg) const = 0;
  /// Empty if the code is installed, otherwise what is missing.
  virtual std::string missing() const = 0;
  /// Sets the ranks and launcher of the following runs of a code that runs under MPI; a code that
  /// does not (silodem has its threads, YADE its one process) ignores it and records ranks 1.
  /// Returns why the code cannot run as asked ("" if it can): its runs are then skipped with that.
  virtual std::string set_parallel(const Parallel&) { return ""; }
  /// silodem's own runs: their progress line (RunOptions::progress_every; < 0: none). The reference
  /// codes write their own logs.
  virtual void set_progress_every(double) {}
  /// Runs the case with a wall-clock limit and writes result files into `dir`.
  virtual BackendResult run(const silodem::CaseConfig& cfg, const std::filesystem::path& dir,
                            double time_limit_s) const = 0;
};

/// silodem, lammps, liggghts, yade — in that order.
std::vector<std::unique_ptr<Backend>> all_backends();
std::unique_ptr<Backend> make_lammps_backend();
std::unique_ptr<Backend> make_liggghts_backend();
std::unique_ptr<Backend> make_yade_backend();

}  // namespace harness
