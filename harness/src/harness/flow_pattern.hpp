#pragma once
// The flow pattern of a hopper silo in discharge, observed and predicted (docs/theory.md §6.1):
// observed from a velocity_field probe as the mass flow index MFI = v_wall / v_axis, the mean
// downward speed of the grains next to the wall over that on the axis at one level (Johanson:
// mass flow when MFI ≥ 0.3); predicted by Jenike's mass-flow boundary for conical hoppers, with the
// angle of internal friction and the wall friction that the virtual material tests measured.
#include <nlohmann/json.hpp>

#include <vector>

#include "harness/checks.hpp"
#include "silodem/case/json_reader.hpp"

namespace harness {

/// {"type": "flow_pattern", "velocity_probe": name, "hopper_wall": a cone, "z": level (m),
///  "wall_friction_from": case, "internal_friction_from": case, "mass_flow_index": 0.3 with
///  "mass_flow_index_source", "boundary_source", "margin_deg": 5}
void validate_flow_pattern(const silodem::JsonReader& r, const silodem::CaseConfig& cfg);

/// Jenike's boundary for a conical hopper as Arnold & McLean approximate it: the largest half-angle
/// from the vertical (deg) that still gives mass flow, θ_c = ½[180° − acos((1 − sin δ)/(2 sin δ))] − φ_w,
/// δ the effective angle of internal friction, φ_w the wall friction angle (both deg). NaN for
/// δ < asin(1/3) ≈ 19.5°, where the approximation has no value.
double conical_mass_flow_boundary_deg(double delta_deg, double phi_w_deg);

/// The mass flow index at the probe's height bin containing z: the mean axial velocity of the
/// outermost cell with a solid fraction of at least 0.2 over that of the innermost (NaN if the
/// axis is not flowing down). `cells` gives which radial bins those were.
struct MassFlowIndex {
  double index = NAN, v_wall = NAN, v_axis = NAN;
  int wall_bin = -1, height_bin = -1;
};
MassFlowIndex mass_flow_index(const CsvTable& field, double z);

std::vector<CheckRow> flow_pattern(const nlohmann::json& spec, const RunContext& ctx);

}  // namespace harness
