#include "harness/flow_pattern.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "harness/janssen_prediction.hpp"
#include "harness/tolerance_source.hpp"

namespace harness {

using nlohmann::json;

namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;
constexpr double kFilled = 0.2;  // a cell with less solid is at the fill's edge or against the wall's bumps

const silodem::WallSpec* find_wall(const silodem::CaseConfig& cfg, const std::string& name) {
  for (const auto& w : cfg.walls)
    if (w.name == name) return &w;
  return nullptr;
}

}  // namespace

double conical_mass_flow_boundary_deg(double delta_deg, double phi_w_deg) {
  const double s = std::sin(delta_deg / kDeg);
  const double c = (1.0 - s) / (2.0 * s);
  if (!(s > 0.0) || c > 1.0) return NAN;
  return 0.5 * (180.0 - std::acos(c) * kDeg) - phi_w_deg;
}

MassFlowIndex mass_flow_index(const CsvTable& field, double z) {
  MassFlowIndex m;
  // The height bin whose cells contain z: the one with the nearest centre.
  double best = INFINITY;
  for (std::size_t i = 0; i < field.size(); ++i)
    if (const double d = std::abs(field.number(i, "z_centre") - z); d < best) best = d, m.height_bin = int(field.number(i, "height_bin"));
  int innermost = -1, outermost = -1;
  for (std::size_t i = 0; i < field.size(); ++i) {
    if (int(field.number(i, "height_bin")) != m.height_bin || field.number(i, "solid_fraction") < kFilled) continue;
    const int b = int(field.number(i, "radial_bin"));
    if (innermost < 0 || b < innermost) innermost = b, m.v_axis = field.number(i, "mean_vz");
    if (b > outermost) outermost = b, m.v_wall = field.number(i, "mean_vz");
  }
  m.wall_bin = outermost;
  if (innermost < 0 || !(m.v_axis < 0.0) || innermost == outermost) return m;
  m.index = m.v_wall / m.v_axis;
  return m;
}

void validate_flow_pattern(const silodem::JsonReader& r, const silodem::CaseConfig& cfg) {
  const std::string probe = r.string("velocity_probe");
  bool found = false;
  for (const auto& p : cfg.probes) found = found || (p.name == probe && p.type == "velocity_field");
  if (!found) r.fail("velocity_probe", "no velocity_field probe named \"" + probe + "\"");
  const silodem::WallSpec* w = find_wall(cfg, r.string("hopper_wall"));
  if (!w || w->type != "cone") r.fail("hopper_wall", "must name a cone wall");
  (void)r.number("z");
  (void)r.string("wall_friction_from");
  (void)r.string("internal_friction_from");
  if (!(r.number("mass_flow_index") > 0.0 && r.number("mass_flow_index") < 1.0))
    r.fail("mass_flow_index", "the index above which the flow is mass flow, in (0, 1)");
  validate_tolerance_source(r, "mass_flow_index");
  validate_tolerance_source(r, "boundary");
  if (!r.has("mass_flow_index_source")) r.fail("mass_flow_index_source", "say where the criterion comes from");
  if (!r.has("boundary_source")) r.fail("boundary_source", "say where the mass-flow boundary comes from");
  if (r.has("margin_deg") && !(r.number("margin_deg") >= 0.0)) r.fail("margin_deg", "must be >= 0");
}

std::vector<CheckRow> flow_pattern(const json& spec, const RunContext& ctx) {
  const std::string probe = spec.at("velocity_probe");
  const silodem::WallSpec& cone = *find_wall(ctx.cfg, spec.at("hopper_wall"));
  const double beta = std::atan((cone.diameter - cone.hole_diameter) / 2.0 / cone.height) * kDeg;
  const MassFlowIndex m = mass_flow_index(ctx.result.probe(probe), spec.at("z").get<double>());
  CheckRow index = report_row(ctx, "mass_flow_index", probe, m.index,
                              "the observed v_wall / v_axis; the flow_pattern_is_mass_flow row judges it");
  index.note = "height bin " + std::to_string(m.height_bin) + ", wall cell = radial bin " + std::to_string(m.wall_bin) +
               ": v_wall = " + std::to_string(m.v_wall) + " m/s, v_axis = " + std::to_string(m.v_axis) + " m/s";
  const double threshold = spec.at("mass_flow_index");
  const double observed = std::isfinite(m.index) ? double(m.index >= threshold) : NAN;
  const std::string source = tolerance_source(spec, "boundary", 0.0) + "; " + tolerance_source(spec, "mass_flow_index", threshold);
  // Without the material tests no pattern is predicted: a judged row that fails, saying why.
  const auto unpredicted = [&](const std::string& why) -> std::vector<CheckRow> {
    CheckRow r = match_row(ctx, "flow_pattern_is_mass_flow", probe, NAN, observed, 0.0, "a prediction that cannot be made fails", false);
    r.note = why;
    return {index, r};
  };
  if (!ctx.earlier_rows) return unpredicted("flow_pattern needs the material tests' rows of the same verify run");
  MeasuredParameter delta, mu;
  try {
    delta = measured_parameter(*ctx.earlier_rows, spec.at("internal_friction_from"), "internal_friction_critical_deg", ctx.variant);
    mu = measured_parameter(*ctx.earlier_rows, spec.at("wall_friction_from"), "wall_friction_mu_w", ctx.variant);
  } catch (const std::runtime_error& e) {
    return unpredicted(e.what());
  }
  const double phi_w = std::atan(mu.mean) * kDeg;
  const double theta_c = conical_mass_flow_boundary_deg(delta.mean, phi_w);
  CheckRow boundary = report_row(ctx, "mass_flow_boundary_deg", cone.name, theta_c,
                                 "Jenike's boundary from the material tests; the pattern row judges the hopper against it", beta);
  boundary.note = "delta = phi_i at critical state = " + std::to_string(delta.mean) + " deg (" + delta.group +
                  "), phi_w = atan(mu_w " + std::to_string(mu.mean) + ") = " + std::to_string(phi_w) +
                  " deg; expected = the hopper's half-angle " + std::to_string(beta) + " deg";
  CheckRow pattern = match_row(ctx, "flow_pattern_is_mass_flow", probe, double(beta < theta_c), observed, 0.0, source, false);
  pattern.note = "1 = mass flow (MFI >= " + std::to_string(threshold) + "), 0 = funnel flow; hopper half-angle " +
                 std::to_string(beta) + " deg against the boundary " + std::to_string(theta_c) + " deg";
  const double margin = spec.value("margin_deg", 5.0);
  if (!(std::abs(beta - theta_c) >= margin))
    to_report(pattern, "the hopper's half-angle is within " + std::to_string(margin) +
                           " deg of the predicted boundary, where neither pattern is predicted");
  return {index, boundary, pattern};
}

}  // namespace harness
