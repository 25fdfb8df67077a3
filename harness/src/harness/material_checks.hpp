#pragma once
// Virtual material tests (EN 1991-4 Annex C on the silo's own grains and wall): the parameters a
// silo engineer measures and the Janssen prediction takes. Each gives a measured value — a report
// row, there is no oracle — and the spread check (across_variants.cpp) its scatter over packings.
#include <nlohmann/json.hpp>

#include <vector>

#include "harness/checks.hpp"
#include "silodem/case/json_reader.hpp"

namespace harness {

/// {"type": "lateral_pressure_ratio", "wall_probe": name, "exclude_bottom_diameters": 0.5,
///  "exclude_top_diameters": 0.5}: a column at rest against a frictionless wall, K = σ_h/σ_v per band
/// of the mantle with σ_v from the slice equilibrium (docs/theory.md §4.1).
void validate_lateral_pressure_ratio(const silodem::JsonReader& r, const silodem::CaseConfig& cfg);
std::vector<CheckRow> lateral_pressure_ratio(const nlohmann::json& spec, const RunContext& ctx);

}  // namespace harness
