#pragma once
// A run shared among MPI processes (`mpirun -np N silodem-mpi run CASE --out DIR`): the step loop of
// run/simulation.cpp over a domain decomposition (mpi/domain.hpp), giving the same bits as the
// one-process run. Version 1 covers the scenes of a settling or flowing bed between wall balls;
// a case that asks for more is refused with the key that is not supported yet (docs/cluster.md).
#include <nlohmann/json.hpp>

#include "silodem/case/case_config.hpp"
#include "silodem/mpi/mpi_partition.hpp"
#include "silodem/run/simulation.hpp"

namespace silodem::mpi {

/// Empty if the decomposition covers the case, else what it does not cover yet.
std::string unsupported_by_ranks(const CaseConfig& cfg);

/// Runs the case on every process of MPI_COMM_WORLD; rank 0 writes the result directory and
/// returns its summary (the others return an empty object).
nlohmann::json run_distributed(const CaseConfig& cfg, const RunOptions& opt, MpiPartition& part);

}  // namespace silodem::mpi
