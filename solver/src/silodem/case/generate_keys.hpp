#pragma once
// Where a case's balls come from besides the listed ones (docs/case-format.md "balls" and
// "generate"): a compact state file (`"balls": {"state_file": …}`) and packings generated from a
// description (`"generate": [...]`, scene/packing_builder.hpp).
#include <filesystem>

#include "silodem/case/case_config.hpp"
#include "silodem/case/json_reader.hpp"

namespace silodem::case_keys {

/// `"balls": {"state_file": PATH}`: every ball of a state file (compact or state.json), appended
/// to cfg.balls; each is checked as a listed ball would be (material, radius, position, velocity).
void read_balls_from_state(const JsonReader& balls, CaseConfig& cfg);

/// Every generator of r["generate"], its grains appended to cfg.balls in array order.
void read_generators(const JsonReader& r, CaseConfig& cfg);

/// A relative `balls.state_file` made absolute against the case file's folder (read_case_json),
/// so that a case read from a file finds its state wherever the reader runs.
void resolve_state_file(nlohmann::json& case_json, const std::filesystem::path& case_file);

}  // namespace silodem::case_keys
