#pragma once
// The Janssen column predicted, not fitted (docs/theory.md §4.3): the wall pressure profile of a
// settled column of frictional grains against Janssen's law evaluated with the K and μ_w that the
// virtual material tests of the same grains and wall measured (lateral_pressure_ratio,
// wall_friction), its tolerance their seed scatter carried through the law.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "harness/checks.hpp"
#include "silodem/case/json_reader.hpp"

namespace harness {

/// {"type": "janssen_prediction", "wall_probe": name, "floor_probe": name (optional),
///  "lateral_pressure_ratio_from": case, "wall_friction_from": case, "coverage": 2,
///  "exclude_bottom_diameters": 0.5, "value": "final" | "mean", "report": why (optional: not judged)}
void validate_janssen_prediction(const silodem::JsonReader& r, const silodem::CaseConfig& cfg);

/// The cases whose rows a check takes (verify runs them first; empty for most checks).
std::vector<std::string> cases_a_check_takes(const nlohmann::json& spec);

/// A material test's mean and scatter for a variant: the spread row of `quantity` in case
/// `from` whose group's axis values all appear in `variant` (throws naming what is missing).
struct MeasuredParameter {
  double mean = NAN, scatter = NAN;
  int realisations = 0;
  std::string group;
};
MeasuredParameter measured_parameter(const std::vector<CheckRow>& rows, const std::string& from,
                                     const std::string& quantity, const std::string& variant);

std::vector<CheckRow> janssen_prediction(const nlohmann::json& spec, const RunContext& ctx);

}  // namespace harness
