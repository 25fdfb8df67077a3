#pragma once
// Where a tolerance written in a case file comes from. Beside a tolerance key K of a check (or of
// a between_codes entry), an optional object K_source says it (docs/case-format.md, "Tolerance
// sources"):
//   {"type": "scheme_bound", "derivation": "<the error bound of the scheme and how it gives K>"}
//   {"type": "seed_scatter", "realisations": n >= 2, "scatter": s > 0, "measured": "<where, optional>"}
//   {"type": "published", "citation": "<author, year, journal or standard, clause>"}
// A tolerance without one makes its rows report rows (check_row.hpp).
#include <nlohmann/json.hpp>

#include <string>

#include "silodem/case/json_reader.hpp"

namespace harness {

/// The key that holds the source of tolerance key `key`: "<key>_source".
std::string source_key(const std::string& key);

/// Validates `<key>_source` of the object `r` reads, if present (throws CaseError with its path).
void validate_tolerance_source(const silodem::JsonReader& r, const std::string& key);

/// The source as a row states it, "" when the spec gives none. `tolerance` is the value it
/// supports: a seed-scatter source also says how many scatters the tolerance is.
std::string tolerance_source(const nlohmann::json& spec, const std::string& key, double tolerance);

}  // namespace harness
