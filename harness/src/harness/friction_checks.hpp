#pragma once
// Checks of the particle-scale friction and Hertz cases against references/friction.hpp
// (docs/theory.md §10): a Hertz impact, an oblique impact in gross sliding, slip to roll on a
// floor, rolling against a rolling couple. Each tolerance is the case file's, with its source beside it (tolerance_source.hpp).
#include <nlohmann/json.hpp>

#include <vector>

#include "harness/checks.hpp"
#include "silodem/case/json_reader.hpp"

namespace harness {

/// {"type": "hertz_impact", "pair_probe", "tolerance"}: largest overlap, duration and (elastic)
/// restitution of the pair's first contact against Hertz's solution.
std::vector<CheckRow> hertz_impact(const nlohmann::json& spec, const RunContext& ctx);
/// {"type": "oblique_impact", "ball_probe", "plane", "tolerance"}: tangential and normal
/// restitution, rebound spin and rebound angle against rigid-body gross sliding; a report row
/// where the incidence is below the sliding limit (no closed form).
std::vector<CheckRow> oblique_impact(const nlohmann::json& spec, const RunContext& ctx);
/// {"type": "slip_to_roll", "ball_probe", "floor", "tolerance"}: speed and spin at the end of
/// the run, sliding (t < t_s) or rolling (t > t_s).
std::vector<CheckRow> slip_to_roll(const nlohmann::json& spec, const RunContext& ctx);
/// {"type": "rolling_resistance", "ball_probe", "floor", "tolerance"}: a ball rolling on the floor
/// (or on it tilted by gravity) against the rolling couple: speed and spin at the end of the run
/// against a = (5/7)(g_t - mu_r g_n R*/r); a ball the couple holds: its displacement, bounded by
/// the springs' elastic deflection (EPSD), or reported (constant torque).
std::vector<CheckRow> rolling_resistance(const nlohmann::json& spec, const RunContext& ctx);

/// The keys of these checks, validated at load (throws CaseError with the path).
void validate_friction_check(const std::string& type, const silodem::JsonReader& r, const silodem::CaseConfig& cfg);

}  // namespace harness
