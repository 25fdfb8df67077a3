#pragma once
// The angle-averaged wall pressure per height band of one wall probe — the profile the silo issue
// compares between codes ("band_pressure" rows; the cross-code rows judge them). On its own a row
// only asserts a finite, non-negative pressure; its worth is in the comparison.
#include <nlohmann/json.hpp>

#include <vector>

#include "harness/checks.hpp"
#include "silodem/case/json_reader.hpp"

namespace harness {

/// {"type": "pressure_profile", "wall_probe": name, "value": "mean" | "final"}
void validate_pressure_profile(const silodem::JsonReader& r, const silodem::CaseConfig& cfg);
std::vector<CheckRow> pressure_profile(const nlohmann::json& spec, const RunContext& ctx);

}  // namespace harness
