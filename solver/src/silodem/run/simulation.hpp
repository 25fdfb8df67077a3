#pragma once
// One run of one case: scene → neighbour search → contact law → integrator → probes → result
// files. Results are written to a sibling temporary directory and renamed into place only when
// complete, so an interrupted or failed run never leaves a directory that looks finished. With a
// "checkpoint" section, the whole state is saved every so often to <out_dir>.checkpoint/, and a
// restart continues from it bitwise (checkpoint/).
#include <nlohmann/json.hpp>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "silodem/case/case_config.hpp"
#include "silodem/core/run_error.hpp"

namespace silodem {


struct RunOptions {
  std::filesystem::path out_dir;
  bool progress = true;   // a progress line on stderr (core/progress.hpp)
  bool banner = true;     // print the derived contact constants at start
  bool restart = false;   // continue from the newest valid checkpoint in <out_dir>.checkpoint/
  std::vector<std::filesystem::path> inputs;  // the case files: no output may be or hold one
  double progress_every = 0.0;  // > 0: a plain progress line every so many seconds; 0: redrawn, on a terminal only
};

/// Runs the case and returns the summary that was written to <out_dir>/summary.json.
nlohmann::json run_case(const CaseConfig& cfg, const RunOptions& opt);

std::string silodem_version();

/// `--out DIR` as a directory path: "DIR/" and "DIR" name the same directory, and its siblings
/// (.partial-<pid>, .failed, .checkpoint) must sit beside it, not in it.
std::filesystem::path normal_out(const std::filesystem::path& dir);

/// The fields every complete run's summary.json starts with: format, status, code, version, case, seed, input.
nlohmann::json complete_summary_head(const CaseConfig& cfg);

/// The neighbour-list skin when the case gives none: a fifth of the smallest radius.
double default_skin(const CaseConfig& cfg);

}  // namespace silodem
