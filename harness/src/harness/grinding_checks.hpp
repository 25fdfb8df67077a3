#pragma once
// The grinding result of a run with breakage (seed 003's mill, docs/model.md §14): the breakable
// material's size distribution against time, rebuilt from the case's grains and breakage.csv.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "harness/checks.hpp"
#include "silodem/case/json_reader.hpp"

namespace harness {

/// {"type": "size_distribution", "material", "every", "sieves": [x, ...], "charge_probe"}: the
/// material's grains start as the case lists them; each row of breakage.csv replaces one grain of
/// radius r by n fragments of r n^(-1/3) (equal masses). At t = 0, every, 2 every, ... and the end:
/// the mass fraction of the material in grains of radius below each sieve x (m) and the number of
/// its grains — reports (the model's toughness is random). Judged: the number of grains the log
/// gives at the end against the charge probe's count (each break adds n − 1), exactly.
std::vector<CheckRow> size_distribution(const nlohmann::json& spec, const RunContext& ctx);

/// The keys of this check, validated at load (throws CaseError with the path).
void validate_size_distribution(const silodem::JsonReader& r, const silodem::CaseConfig& cfg);

}  // namespace harness
