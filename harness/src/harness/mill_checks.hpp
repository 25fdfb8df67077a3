#pragma once
// Checks of a charge in a turning drum (seed 003's mill, docs/model.md §12, §14): the torque
// identity, the drum's power, the regime figures and the charge's volume under breakage.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "harness/checks.hpp"
#include "silodem/case/json_reader.hpp"

namespace harness {

/// {"type": "torque_identity", "wall_probe", "charge_probe"}: over the common window, the drum's
/// mean torque about its axis against M (⟨x̄⟩ − c) × g − ΔL/τ (the charge's angular momentum
/// balance: contacts inside the charge cancel), judged within the sampled means' end terms; and
/// the drum's power against −Ω·T (rigid-body wall velocities), judged to round-off.
std::vector<CheckRow> torque_identity(const nlohmann::json& spec, const RunContext& ctx);
/// {"type": "mill_regime", "charge_probe", "wall"}: Froude number Ω² R/g, Ω/Ω_c, the charge's
/// dynamic angle (its centre of mass's bearing from below the axis: a flat-surfaced charge's
/// surface tilt), its kinetic energy per unit mass, and Mellmann's (2001) regime for the Froude
/// number — reports.
std::vector<CheckRow> mill_regime(const nlohmann::json& spec, const RunContext& ctx);
/// {"type": "charge_volume", "charge_probe"}: Σ (4/3)π r³ of the charge at the end against the
/// start, judged to round-off (fragments keep their parent's volume), with the breaks reported.
std::vector<CheckRow> charge_volume(const nlohmann::json& spec, const RunContext& ctx);

/// The keys of these checks, validated at load (throws CaseError with the path).
void validate_mill_check(const std::string& type, const silodem::JsonReader& r, const silodem::CaseConfig& cfg);

}  // namespace harness
