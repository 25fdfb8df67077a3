#pragma once
// `silodem verify`: validate every case and variant first, then run them, read the result files,
// apply the case's checks and report a verdict per quantity.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <optional>
#include <vector>

#include "harness/checks.hpp"
#include "harness/sweep/executor.hpp"

namespace harness {

struct VerifyOptions {
  std::filesystem::path out_root = "results";
  std::optional<std::filesystem::path> report;  // Markdown report
  bool progress = true;
  std::function<void()> before_first_run;  // once every input is checked (main prepares the outputs)
  /// The material tests' rows of an earlier verify (its verdicts.json): cases that checks take
  /// and this command does not run are read from there (taken_rows.hpp).
  std::optional<std::filesystem::path> material_tests_from;
  /// Who runs the case variants (sweep/executor.hpp): null runs them in this process, one after another.
  SweepExecutor* executor = nullptr;
  /// The silodem binary named in the plan's commands (for the reader; the executors take their own).
  std::string silodem_binary = "silodem";
  /// Keep the results of an earlier sweep into the same folder that are complete, verify against
  /// their manifests and were run from the same case input; run only the others.
  bool resume = false;
};

struct VerifyOutcome {
  std::vector<CheckRow> rows;
  std::vector<std::pair<std::string, double>> run_seconds;  // (case/variant, wall seconds)
  std::vector<std::string> ledgers;  // Markdown table rows of the ledger comparison (compare only)
  bool all_pass() const;
};

/// Validates a case file, its variants and its checks without running anything; returns the number
/// of runs `verify` would make. Throws silodem::CaseError naming the JSON path.
std::size_t validate_verification(const std::filesystem::path& case_file);

/// The case JSON of one verify variant of a case file, by its label (as verify prints it). Throws
/// silodem::CaseError for a file that does not load or a label it does not have.
nlohmann::json verify_variant_json(const std::filesystem::path& case_file, const std::string& label);

/// Throws silodem::CaseError for bad input before anything runs.
VerifyOutcome verify_cases(const std::vector<std::filesystem::path>& case_files, const VerifyOptions& opt);

}  // namespace harness
