#pragma once
// The case file's "breakage" section (docs/case-format.md "Breakage"; docs/model.md §14).
#include "silodem/case/case_config.hpp"
#include "silodem/case/json_reader.hpp"

namespace silodem::case_keys {

/// Reads the breakage model; refuses materials the case does not define, a law it cannot run
/// (breakage is built on Hertz contacts) and counts that cannot split a grain.
BreakageSpec read_breakage(const JsonReader& r, const CaseConfig& cfg);

}  // namespace silodem::case_keys
