// silodem-mpi: one run shared among the processes of an MPI launch (mpi/distributed_run.hpp).
//   mpirun -np N silodem-mpi run CASE --out DIR [--quiet] [--progress-every S]
// A separate program, so that the solver most runs use neither links MPI nor starts it.
#include <mpi.h>

#include <cstdio>
#include <cstdlib>
#include <new>
#include <string>

#include "silodem/case/case_error.hpp"
#include "silodem/case/case_loader.hpp"
#include "silodem/core/job_stop.hpp"
#include "silodem/core/run_error.hpp"
#include "silodem/mpi/distributed_run.hpp"
#include "silodem/output/result_dir.hpp"

namespace {

constexpr const char* kUsage =
    "usage: mpirun -np N silodem-mpi run CASE --out DIR [--quiet] [--progress-every S]\n"
    "  One run of CASE shared among the N processes, with the same result files, bit for bit, as\n"
    "  `silodem run CASE --out DIR` on one process. Cases with features the decomposition does not\n"
    "  cover yet are refused, naming the feature (docs/cluster.md).\n";

/// Ends every process: one that stops alone would leave the others waiting in a collective call.
[[noreturn]] void stop_all(int rank, int code, const char* what, const char* message) {
  std::fprintf(stderr, "silodem-mpi (rank %d): %s%s\n", rank, what, message);
  std::fflush(stderr);
  MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  std::string case_file, out;
  bool quiet = false;
  double progress_every = 0.0;
  const bool run = argc >= 2 && std::string(argv[1]) == "run";
  for (int i = 2; run && i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--out" && i + 1 < argc) out = argv[++i];
    else if (a == "--quiet") quiet = true;
    else if (a == "--progress-every" && i + 1 < argc) progress_every = std::atof(argv[++i]);
    else if (a.rfind("--", 0) != 0 && case_file.empty()) case_file = a;
    else stop_all(rank, 2, "unknown or incomplete option ", (a + "\n" + kUsage).c_str());
  }
  if (!run || case_file.empty() || out.empty()) stop_all(rank, 2, "", kUsage);
  try {
    silodem::set_command_line(argc, argv);
    const silodem::CaseConfig cfg = silodem::load_case_file(case_file);
    silodem::mpi::MpiPartition part;
    silodem::RunOptions opt{out, !quiet, !quiet};
    opt.progress_every = progress_every;
    opt.inputs = {case_file};
    const auto summary = silodem::mpi::run_distributed(cfg, opt, part);
    if (rank == 0)
      std::printf("%s: %ld steps on %d processes, t = %.6g s, %.3g s wall, energy drift %.3e -> %s\n", cfg.name.c_str(),
                  summary["run"]["steps"].get<long>(), part.ranks(), summary["run"]["time"].get<double>(),
                  summary["run"]["wall_seconds"].get<double>(), summary["energy"]["relative_drift"].get<double>(), out.c_str());
  } catch (const silodem::CaseError& e) {
    stop_all(rank, 2, "invalid input: ", e.what());
  } catch (const silodem::RunError& e) {
    stop_all(rank, 3, "run stopped: ", e.what());
  } catch (const silodem::JobStop& e) {
    stop_all(rank, e.exit_code(), "", e.what());
  } catch (const std::bad_alloc&) {
    stop_all(rank, 4, "stopped: out of memory", "");
  } catch (const std::exception& e) {
    stop_all(rank, 4, "internal error: ", e.what());
  }
  MPI_Finalize();
  return 0;
}
