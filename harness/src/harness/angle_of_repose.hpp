#pragma once
// The angle of repose of a heap at rest (docs/theory.md §4.5): the slope of the heap's surface
// profile about a wall's axis (the lifted tube of the lifted-cylinder test), from the final state.
#include <nlohmann/json.hpp>

#include <vector>

#include "harness/checks.hpp"
#include "silodem/case/json_reader.hpp"

namespace harness {

/// A heap's surface: the highest grain top per radial bin about the axis, from the axis outwards.
struct HeapProfile {
  std::vector<double> r, height;  // bin centre (m from the axis), surface above the heap's foot (m)
};
HeapProfile heap_profile(const std::vector<silodem::BallSpec>& balls, double axis_x, double axis_y, double bin_width);

/// The line fitted to the profile between fit_from and fit_to of its peak height, walking out from
/// the axis until the surface first drops below fit_from (grains rolled away beyond it do not count).
struct SlopeFit {
  double angle_deg = NAN, r2 = NAN;
  int bins = 0;
};
SlopeFit heap_slope(const HeapProfile& p, double fit_from, double fit_to);

/// {"type": "angle_of_repose", "axis_wall": a cylinder wall (its centre is the heap's axis),
///  "fit_from": 0.25, "fit_to": 0.75, "bin_width": m (default: the largest grain's diameter)}
void validate_angle_of_repose(const silodem::JsonReader& r, const silodem::CaseConfig& cfg);
std::vector<CheckRow> angle_of_repose(const nlohmann::json& spec, const RunContext& ctx);

}  // namespace harness
