#pragma once
// Checks of the silo cases: Janssen, Beverloo, sudden closure, discharge factor, static balance,
// and the angle-averaged wall pressure per height band — the profile the silo issue compares
// between codes ("band_pressure" report rows; the cross-code rows judge them). What Janssen,
// Beverloo and EN 1991-4 publish for frictional grains is reported for frictionless ones.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "harness/checks.hpp"
#include "silodem/case/json_reader.hpp"

namespace harness {

/// {"type": "pressure_profile", "wall_probe": name, "value": "mean" | "final"}
void validate_pressure_profile(const silodem::JsonReader& r, const silodem::CaseConfig& cfg);
/// Janssen fit of a settled column (docs/theory.md §4–5), EN 1991-4 filling pressure, weight balance.
std::vector<CheckRow> janssen(const nlohmann::json& spec, const RunContext& ctx);
/// Steady discharge against Beverloo (docs/theory.md §6).
std::vector<CheckRow> beverloo(const nlohmann::json& spec, const RunContext& ctx);
/// Sudden closure: pressure peak and mean after the closing instant against before (docs/model.md §7.3).
std::vector<CheckRow> closure_overpressure(const nlohmann::json& spec, const RunContext& ctx);

std::vector<CheckRow> pressure_profile(const nlohmann::json& spec, const RunContext& ctx);

/// The discharge factor (EN 1991-4 §5.2.2, C_h = 1.15 for silos not discharged from the top): wall
/// pressure during discharge over the pressure after filling, per height band and overall.
/// {"type": "discharge_factor", "filled_probe", "discharge_probe", "C_h": 1.15, "tolerance"}
void validate_discharge_factor(const silodem::JsonReader& r, const silodem::CaseConfig& cfg);
std::vector<CheckRow> discharge_factor(const nlohmann::json& spec, const RunContext& ctx);

/// A silo at rest: the walls carry the weight of the fill; with drops, enough of them were placed.
/// {"type": "static_balance", "tolerance": number | "stop_test", "min_placed_fraction"}
void validate_static_balance(const silodem::JsonReader& r, const silodem::CaseConfig& cfg);
std::vector<CheckRow> static_balance(const nlohmann::json& spec, const RunContext& ctx);

/// A weight-balance tolerance `key`: a number > 0 (with its source beside it) or "stop_test", the
/// bound p_ft the stop tests guarantee at rest; `required` or optional.
void validate_stop_test_tolerance(const silodem::JsonReader& r, const std::string& key, bool required);

}  // namespace harness
