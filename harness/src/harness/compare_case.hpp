#pragma once
// A case's "compare" section read and checked: its variants' configurations, the checks, the
// between-codes entries with their tolerance sources, the shared state and the seeds
// (docs/case-format.md, "compare"). Everything is validated here, before any run.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "harness/variants.hpp"
#include "silodem/case/case_config.hpp"

namespace harness {

struct Between {
  std::string quantity;
  double tolerance;
  bool relative_to_largest = false;  // error relative to the largest value of the profile, not each value
  bool absolute = false;             // plain difference (values already dimensionless, e.g. energy fractions)
  std::string source;                // where the tolerance comes from ("": none, the rows report)
  std::vector<std::string> codes;    // the reference codes it applies to (empty: all)
  std::string report;                // why these codes' differences are reported, not judged ("": judged)
  std::vector<std::string> variants;  // the compare variants it applies to, by label ("run=a"; empty: all)
  bool at_frames = false;  // silodem's value from the rebuild of its dump, at the codes' frames (else its own probes')
  bool seeds_mean = false;  // silodem's value the mean of its realisations (its run and one per seed), not its run's
};


struct PreparedCompare {
  std::filesystem::path file;  // absolute (compare's jobs prepare the case again from it)
  std::string name;
  bool has_compare = true;  // a verify-only case is reported as skipped, not refused
  nlohmann::json checks;
  std::vector<Between> between;
  double ledger_tolerance = 0.0;
  std::string ledger_source;
  double time_limit = 600.0;
  double from_state_at = 0.0;  // > 0: every code starts from the state silodem reaches at this time
  std::optional<silodem::CaseConfig> lead;  // the case as written (silodem's own protocol) that makes that state
  std::uint64_t seed = 0;                   // the case's own
  std::vector<std::uint64_t> seeds;         // further realisations, silodem only (seed scatter)
  std::vector<silodem::CaseConfig> seed_leads;                  // (b): the shared state with each seed
  std::vector<std::vector<silodem::CaseConfig>> seed_configs;  // (a): [seed][variant], the whole run with each seed
  std::vector<std::string> codes;
  std::map<std::string, std::string> left_out;  // code -> why the case does not run it (a skip row)
  std::vector<Variant> variants;
  std::vector<silodem::CaseConfig> configs;
};

/// Reads and validates the compare section of a case file (throws silodem::CaseError naming the
/// file and the JSON path); `known_codes` are the backends' codes.
PreparedCompare prepare_compare(const std::filesystem::path& file, const std::vector<std::string>& known_codes);

}  // namespace harness
