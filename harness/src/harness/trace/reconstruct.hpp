#pragma once
// Rebuilds a run's result files from its particle dumps, the same way for every code: the energy
// ledger (kinetic, gravitational, elastic and dashpot power from the states, with this project's
// contact law evaluated on each dumped state), the probes (by the solver's own probe classes), and
// the wall load (from the code's own dumped forces on wall balls). The comparator then reads the
// result files without knowing which code wrote the dump.
#include <nlohmann/json.hpp>

#include <filesystem>

#include "harness/backends/translation.hpp"
#include "silodem/case/case_config.hpp"

namespace harness {

/// Writes <out>/series.csv, <out>/probes/*.csv and <out>/summary.json (`meta` merged in:
/// code, version, input, command, wall time, exit status). Dump frames must be at a fixed step
/// interval; the ledger integrates the dashpot power over that interval.
nlohmann::json reconstruct_result(const silodem::CaseConfig& cfg, const Translation& tr,
                                  const std::filesystem::path& dump, const std::filesystem::path& out,
                                  const nlohmann::json& meta);

}  // namespace harness
