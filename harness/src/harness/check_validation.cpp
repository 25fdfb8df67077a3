#include "harness/checks.hpp"

#include <algorithm>

#include "harness/friction_checks.hpp"
#include "harness/grinding_checks.hpp"
#include "harness/mill_checks.hpp"
#include "harness/tray_checks.hpp"
#include "harness/flow_pattern.hpp"
#include "harness/janssen_prediction.hpp"
#include "harness/angle_of_repose.hpp"
#include "harness/material_checks.hpp"
#include "harness/silo_checks.hpp"
#include "harness/tolerance_source.hpp"
#include "silodem/case/case_error.hpp"
#include "silodem/case/json_reader.hpp"

namespace harness {

using nlohmann::json;
using silodem::CaseConfig;

void validate_check(const json& spec, const std::string& path, const CaseConfig& cfg, const std::vector<std::string>& axes) {
  const silodem::JsonReader r(spec, path);
  const std::string type = r.choice_or("type",
                                       {"restitution", "cohesion_separation", "cohesion_energy", "first_contact",
                                        "rebound_height", "energy_balance", "convergence", "janssen", "beverloo", "beverloo_fit",
                                        "closure_overpressure", "pressure_profile", "discharge_factor", "static_balance",
                                        "energy_terms", "hertz_impact", "oblique_impact", "slip_to_roll",
                                        "rolling_resistance", "lateral_pressure_ratio", "wall_friction", "direct_shear", "angle_of_repose", "janssen_prediction", "flow_pattern",
                                        "torque_identity", "mill_regime", "charge_volume", "size_distribution", "slot_discharge", "spread"},
                                       "");
  const auto find_probe = [&](const std::string& name, const std::string& kind) -> const silodem::ProbeSpec* {
    for (const auto& p : cfg.probes)
      if (p.name == name && p.type == kind) return &p;
    return nullptr;
  };
  const auto need_probe = [&](const silodem::JsonReader& rd, const std::string& key, const std::string& kind) {
    const std::string name = rd.string(key);
    if (!find_probe(name, kind)) rd.fail(key, "no " + kind + " probe named \"" + name + "\"");
    return name;
  };
  const auto need_ball = [&](const std::string& key) {
    const std::string id = r.string(key);
    for (const auto& b : cfg.balls)
      if (b.id == id) return;
    r.fail(key, "no ball with id \"" + id + "\"");
  };
  // A number (its source optionally beside it, tolerance_source.hpp) or the check's own bound.
  const auto tolerance = [&](bool scheme_bound_allowed) {
    const json& t = r.raw("tolerance");
    if (!(t.is_number() && t.get<double>() > 0.0) && !(scheme_bound_allowed && t == "scheme_bound"))
      r.fail("tolerance", scheme_bound_allowed ? "a number > 0 or \"scheme_bound\"" : "a number > 0");
    if (t.is_string() && r.has(source_key("tolerance")))
      r.fail(source_key("tolerance"), "\"scheme_bound\" states its own source; give a source only for a number");
    validate_tolerance_source(r, "tolerance");
  };
  if (type == "restitution" || type == "cohesion_separation" || type == "cohesion_energy") {
    if (r.has("probes")) {
      const json& ps = r.array("probes");
      for (std::size_t i = 0; i < ps.size(); ++i)
        if (!ps[i].is_string() || !find_probe(ps[i].get<std::string>(), "pair"))
          throw silodem::CaseError(r.child_path("probes") + "[" + std::to_string(i) + "]", "not a pair probe");
    }
    tolerance(true);
    if (type == "restitution") (void)r.choice_or("oracle", {"as_integrated", "exact"}, "as_integrated");
  } else if (type == "first_contact") {
    need_probe(r, "drops_probe", "drops");
    const long k = r.integer_or("drop", 0);
    if (k < 0 || !cfg.drops || k >= cfg.drops->count) r.fail("drop", "no such drop in \"drops\"");
    need_ball("obstacle");
    const silodem::JsonReader tw = r.object("twin");
    need_probe(tw, "pair_probe", "pair");
    if (tw.has("other_pair_probes")) {
      const json& ps = tw.array("other_pair_probes");
      for (std::size_t i = 0; i < ps.size(); ++i)
        if (!ps[i].is_string() || !find_probe(ps[i].get<std::string>(), "pair"))
          throw silodem::CaseError(tw.child_path("other_pair_probes") + "[" + std::to_string(i) + "]", "not a pair probe");
    }
    tw.finish();
  } else if (type == "rebound_height") {
    need_probe(r, "ball_probe", "ball");
    need_ball("obstacle");
    tolerance(true);
  } else if (type == "energy_balance") {
    tolerance(false);
  } else if (type == "beverloo") {
    need_probe(r, "outflow_probe", "outflow");
    for (const char* k : {"from_time", "bulk_density", "grain_diameter"})
      if (!(r.number(k) > 0.0)) r.fail(k, "must be > 0");
    const std::string wall = r.string("outlet_wall");
    if (!(outlet_diameter_of(cfg, wall) > 0.0))
      r.fail("outlet_wall", "no wall \"" + wall + "\" with an outlet (a wall's hole_diameter, a smooth hopper's lower end)");
    for (const char* k : {"C", "k", "max_scatter"})
      if (r.has(k)) (void)r.number(k);
    validate_tolerance_source(r, "max_scatter");
    tolerance(false);
  } else if (type == "closure_overpressure") {
    const std::string name = need_probe(r, "wall_probe", "wall_pressure");
    for (const auto& p : cfg.probes)
      if (p.name == name && !(p.history_interval > 0.0)) r.fail("wall_probe", "the probe needs a history_interval");
    if (!(r.number("close_time") > 0.0)) r.fail("close_time", "must be > 0");
    if (!(r.number("window") > 0.0)) r.fail("window", "must be > 0");
    if (r.has("min_rise")) (void)r.number("min_rise");
    validate_tolerance_source(r, "min_rise");
  } else if (type == "beverloo_fit") {
    const std::string axis = r.string("axis");
    if (std::find(axes.begin(), axes.end(), axis) == axes.end())
      r.fail("axis", "\"" + axis + "\" is not an axis of verify.variants");
    const std::string wall = r.string("outlet_wall");
    if (!(outlet_diameter_of(cfg, wall) > 0.0))
      r.fail("outlet_wall", "no wall \"" + wall + "\" with an outlet (a wall's hole_diameter, a smooth hopper's lower end)");
    for (const char* k : {"bulk_density", "grain_diameter"})
      if (!(r.number(k) > 0.0)) r.fail(k, "must be > 0");
    if (!(r.number("k_min") < r.number("k_max"))) r.fail("k_max", "must exceed k_min");
    const double r2 = r.number("min_r2");
    if (!(r2 > 0.0 && r2 <= 1.0)) r.fail("min_r2", "must be in (0, 1]");
    validate_tolerance_source(r, "min_r2");
    for (const char* k : {"C_range", "k_range"}) {
      if (!r.has(k)) continue;
      const json& range = r.raw(k);
      if (!(range.is_array() && range.size() == 2 && range[0].is_number() && range[1].is_number() &&
            range[0].get<double>() < range[1].get<double>()))
        r.fail(k, "[low, high] with low < high");
      validate_tolerance_source(r, k);
    }
  } else if (type == "janssen") {
    need_probe(r, "wall_probe", "wall_pressure");
    if (!(r.number("ball_diameter") > 0.0)) r.fail("ball_diameter", "must be > 0 (depths are reported in diameters)");
    for (const char* k : {"exclude_bottom_diameters", "min_r2", "K_min", "K_max", "phi_im_deg", "en_tolerance"})
      if (r.has(k)) (void)r.number(k);
    validate_stop_test_tolerance(r, "weight_tolerance", false);
    for (const char* k : {"min_r2", "en_tolerance"}) validate_tolerance_source(r, k);
  } else if (type == "pressure_profile") {
    validate_pressure_profile(r, cfg);
  } else if (type == "discharge_factor") {
    validate_discharge_factor(r, cfg);
  } else if (type == "static_balance") {
    validate_static_balance(r, cfg);
  } else if (type == "hertz_impact" || type == "oblique_impact" || type == "slip_to_roll" ||
             type == "rolling_resistance") {
    validate_friction_check(type, r, cfg);
  } else if (type == "slot_discharge") {
    validate_tray_check(r, cfg);
    return;
  } else if (type == "torque_identity" || type == "mill_regime" || type == "charge_volume") {
    validate_mill_check(type, r, cfg);
  } else if (type == "size_distribution") {
    validate_size_distribution(r, cfg);
  } else if (type == "janssen_prediction") {
    validate_janssen_prediction(r, cfg);
  } else if (type == "flow_pattern") {
    validate_flow_pattern(r, cfg);
  } else if (type == "lateral_pressure_ratio" || type == "wall_friction") {
    validate_mantle_band_check(r, cfg);
  } else if (type == "direct_shear") {
    validate_direct_shear(r, cfg);
  } else if (type == "angle_of_repose") {
    validate_angle_of_repose(r, cfg);
  } else if (type == "spread") {
    const std::string axis = r.string("axis");
    if (std::find(axes.begin(), axes.end(), axis) == axes.end())
      r.fail("axis", "\"" + axis + "\" is not an axis of verify.variants");
    const json& q = r.array("quantities");
    if (q.empty()) r.fail("quantities", "must name at least one quantity");
    for (const auto& x : q)
      if (!x.is_string()) r.fail("quantities", "must be quantity names (strings)");
  } else if (type == "convergence") {
    (void)r.choice_or("quantity", {"restitution", "contact_duration"}, "restitution");
    const std::string axis = r.string("axis");
    if (std::find(axes.begin(), axes.end(), axis) == axes.end())
      r.fail("axis", "\"" + axis + "\" is not an axis of verify.variants");
  }
  r.finish();
}


}  // namespace harness
