#pragma once
// Checks of seed 001's vibrating tray (docs/model.md §12): the discharge through each slot and the
// count of grains.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "harness/checks.hpp"
#include "silodem/case/json_reader.hpp"

namespace harness {

/// {"type": "slot_discharge", "outflow_probe", "tray", "from_time"}: each exit goes to the slot
/// nearest its x. Per slot, a `report` row of the mass rate after `from_time` (kg/s) and the
/// mass through it; `grain_count`: exits + grains left = grains at the start, judged exactly; the
/// tray's vibration as Γ = A (2πf)²/g, reported.
std::vector<CheckRow> slot_discharge(const nlohmann::json& spec, const RunContext& ctx);

/// The keys of the check, validated at load (throws CaseError with the path).
void validate_tray_check(const silodem::JsonReader& r, const silodem::CaseConfig& cfg);

}  // namespace harness
