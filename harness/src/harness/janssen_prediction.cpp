#include "harness/janssen_prediction.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "harness/material_checks.hpp"
#include "harness/tolerance_source.hpp"
#include "references/janssen.hpp"

namespace harness {

using nlohmann::json;

namespace {

std::vector<std::string> tokens(const std::string& label) {
  std::vector<std::string> out;
  std::stringstream s(label);
  for (std::string t; std::getline(s, t, ',');) out.push_back(t);
  return out;
}

bool contains_all(const std::string& variant, const std::string& group) {
  const auto have = tokens(variant);
  for (const auto& t : tokens(group))
    if (std::find(have.begin(), have.end(), t) == have.end()) return false;
  return true;
}

/// Janssen's horizontal pressure at depth z and its derivatives in K and μ_w (docs/theory.md §4):
/// p = γD/(4μ) (1 − e^{−x}), x = 4μKz/D.
struct JanssenPoint {
  double p, dp_dK, dp_dmu;
};
JanssenPoint janssen_point(double gamma, double D, double K, double mu, double z) {
  const double e = std::exp(-4.0 * mu * K * z / D);
  const double p = gamma * D / (4.0 * mu) * (1.0 - e);
  return {p, gamma * z * e, -p / mu + gamma * K * z * e / mu};
}

/// The prediction could not be made (no material test for this variant): a judged row that fails.
CheckRow unpredicted(const RunContext& ctx, const std::string& probe, const std::string& why) {
  CheckRow r = match_row(ctx, "janssen_predicted_profile", probe, 1.0, NAN, 0.0,
                         "a prediction that cannot be made fails");
  r.note = why;
  return r;
}

}  // namespace

void validate_janssen_prediction(const silodem::JsonReader& r, const silodem::CaseConfig& cfg) {
  const auto cylinder_probe = [&](const std::string& key, const char* type) {
    const std::string name = r.string(key);
    for (const auto& p : cfg.probes)
      if (p.name == name && p.type == "wall_pressure")
        for (const auto& w : cfg.walls)
          if (w.name == p.wall && w.type == type) return;
    r.fail(key, "no wall_pressure probe named \"" + name + "\" on a " + type);
  };
  cylinder_probe("wall_probe", "cylinder");
  if (r.has("floor_probe")) cylinder_probe("floor_probe", "disk");
  (void)r.string("lateral_pressure_ratio_from");
  (void)r.string("wall_friction_from");
  if (r.has("internal_friction_from")) (void)r.string("internal_friction_from");
  if (r.has("coverage") && !(r.number("coverage") > 0.0)) r.fail("coverage", "must be > 0");
  if (r.has("value")) (void)r.choice_or("value", {"final", "mean"}, "final");
  if (r.has("K_factor") && !(r.number("K_factor") > 0.0)) r.fail("K_factor", "must be > 0");
  validate_tolerance_source(r, "K_factor");
  if (r.has("column_scatter") && !(r.number("column_scatter") >= 0.0)) r.fail("column_scatter", "must be >= 0");
  validate_tolerance_source(r, "column_scatter");
  if (r.has("report") && r.string("report").find_first_not_of(" \t\n") == std::string::npos)
    r.fail("report", "must say why the profile is reported, not judged");
  if (r.has("exclude_bottom_diameters") && !(r.number("exclude_bottom_diameters") >= 0.0))
    r.fail("exclude_bottom_diameters", "must be >= 0");
}

std::vector<std::string> cases_a_check_takes(const json& spec) {
  if (spec.value("type", "") == "flow_pattern") return {spec.at("wall_friction_from"), spec.at("internal_friction_from")};
  if (spec.value("type", "") != "janssen_prediction") return {};
  std::vector<std::string> out = {spec.at("lateral_pressure_ratio_from"), spec.at("wall_friction_from")};
  if (spec.contains("internal_friction_from")) out.push_back(spec.at("internal_friction_from"));
  return out;
}

MeasuredParameter measured_parameter(const std::vector<CheckRow>& rows, const std::string& from,
                                     const std::string& quantity, const std::string& variant) {
  std::vector<const CheckRow*> found;
  for (const auto& r : rows)
    if (r.case_name == from && r.quantity == quantity + "_spread" && contains_all(variant, r.variant)) found.push_back(&r);
  if (found.size() != 1)
    throw std::runtime_error(std::to_string(found.size()) + " spread rows of " + quantity + " in case " + from +
                             " match the variant \"" + variant + "\" (one needed: the material test's axes, but for "
                             "its realisations, must be the column's)");
  MeasuredParameter m{found[0]->expected, found[0]->measured, 0, found[0]->variant};
  m.realisations = std::atoi(found[0]->note.c_str());  // "N realisations" (across_variants.cpp spread_rows)
  return m;
}

namespace {

/// The bands of the profile that Janssen's law is held to: below the surface, above the excluded
/// bottom, with their measured mean pressure.
struct Band {
  int index;
  double depth, measured;
};
/// The probe column the check reads: the final state or the probe's time mean.
std::string pressure_column(const json& spec) {
  return spec.value("value", "final") == "mean" ? "pressure_mean" : "pressure_final";
}

std::vector<Band> profile_bands(const json& spec, const ColumnInWall& c) {
  const std::string column = pressure_column(spec);
  std::map<int, std::pair<double, int>> band;
  for (std::size_t i = 0; i < c.probe.size(); ++i) {
    auto& b = band[int(c.probe.number(i, "height_bin"))];
    b.first += c.probe.number(i, column);
    ++b.second;
  }
  const int bins = int(band.size());
  const double lo = c.z_floor + spec.value("exclude_bottom_diameters", 0.5) * c.D;
  std::vector<Band> out;
  for (const auto& [h, v] : band) {
    const double z_mid = c.band_mid(h, bins);
    if (z_mid < c.z_top && z_mid >= lo) out.push_back({h, c.z_top - z_mid, v.first / v.second});
  }
  return out;
}

/// Σ measured / Σ predicted over the bands, and the relative first-order effect of the parameters'
/// scatter on it.
struct ProfileRatio {
  double ratio = NAN, sigma_params = NAN;
};
ProfileRatio profile_ratio(const std::vector<Band>& bands, const ColumnInWall& c, const MeasuredParameter& K,
                           const MeasuredParameter& mu) {
  double measured = 0.0, predicted = 0.0, dK = 0.0, dmu = 0.0;
  for (const Band& b : bands) {
    const JanssenPoint j = janssen_point(c.gamma, c.D, K.mean, mu.mean, b.depth);
    measured += b.measured, predicted += j.p, dK += j.dp_dK, dmu += j.dp_dmu;
  }
  if (bands.empty()) return {};
  return {measured / predicted, std::hypot(dK * K.scatter, dmu * mu.scatter) / predicted};
}

std::string parameters_text(const MeasuredParameter& K, const MeasuredParameter& mu, double gamma) {
  return "K = " + std::to_string(K.mean) + " +/- " + std::to_string(K.scatter) + ", mu_w = " + std::to_string(mu.mean) +
         " +/- " + std::to_string(mu.scatter) + " (groups " + K.group + ", " + mu.group + "), gamma = " +
         std::to_string(gamma) + " N/m^3";
}

/// The judged profile row of one route to K: its tolerance the material tests' scatter through the
/// law and the column's own scatter between packings (the case's measured `column_scatter`), in
/// quadrature, times the coverage factor.
CheckRow profile_row(const json& spec, const RunContext& ctx, const std::string& quantity, const std::string& probe,
                     const ProfileRatio& pr, int realisations, const std::string& route_source) {
  const double coverage = spec.value("coverage", 2.0), sigma_column = spec.value("column_scatter", 0.0);
  const double sigma = std::hypot(pr.sigma_params, sigma_column);
  std::string source;
  if (std::isfinite(pr.ratio) && realisations >= 2 && pr.sigma_params > 0.0) {
    char b[400];
    std::snprintf(b, sizeof b,
                  "seed scatter of the material tests (at least %d packings each) through Janssen's law, %.3g of the "
                  "profile, and of the column between packings, %.3g; tolerance %.3g x their sum in quadrature",
                  realisations, pr.sigma_params, sigma_column, coverage);
    source = b;
    if (spec.contains("column_scatter_source")) source += "; column: " + tolerance_source(spec, "column_scatter", sigma_column);
    source += route_source;
  }
  CheckRow r = match_row(ctx, quantity, probe, 1.0, pr.ratio, coverage * sigma, source);
  if (spec.contains("report")) to_report(r, spec.at("report").get<std::string>());
  return r;
}

/// EN 1991-4's own K from the angle of internal friction, K = 1.1 (1 − sin φ_i), its scatter
/// 1.1 cos φ_i σ_φ (docs/theory.md §4.4, §5).
MeasuredParameter en_K_from_phi(const MeasuredParameter& phi_deg) {
  const double phi = phi_deg.mean * std::numbers::pi / 180.0, sd = phi_deg.scatter * std::numbers::pi / 180.0;
  return {references::en1991_4_K(phi), std::abs(references::en1991_4_dK_dphi(phi)) * sd, phi_deg.realisations,
          phi_deg.group + " (phi_i = " + std::to_string(phi_deg.mean) + " +/- " + std::to_string(phi_deg.scatter) +
              " deg)"};
}

}  // namespace

std::vector<CheckRow> janssen_prediction(const json& spec, const RunContext& ctx) {
  const std::string probe = spec.at("wall_probe");
  if (!ctx.earlier_rows) return {unpredicted(ctx, probe, "janssen_prediction needs the material tests' rows of the same verify run")};
  MeasuredParameter K, mu, phi;
  const bool en_route = spec.contains("internal_friction_from");
  try {
    K = measured_parameter(*ctx.earlier_rows, spec.at("lateral_pressure_ratio_from"), "lateral_pressure_ratio_K", ctx.variant);
    mu = measured_parameter(*ctx.earlier_rows, spec.at("wall_friction_from"), "wall_friction_mu_w", ctx.variant);
    if (en_route)
      phi = measured_parameter(*ctx.earlier_rows, spec.at("internal_friction_from"), "internal_friction_peak_deg", ctx.variant);
  } catch (const std::exception& e) {
    return {unpredicted(ctx, probe, e.what())};
  }
  // The silo's K from the test's K_o (EN 1991-4 C.6: K_m = 1.1 K_o), if the case says so.
  const double K_factor = spec.value("K_factor", 1.0);
  K.mean *= K_factor, K.scatter *= K_factor;
  const ColumnInWall c = column_in_wall(probe, ctx);  // γ: the column's own bulk unit weight
  const std::vector<Band> bands = profile_bands(spec, c);
  std::vector<CheckRow> out;
  for (const Band& b : bands) {
    const double predicted = janssen_point(c.gamma, c.D, K.mean, mu.mean, b.depth).p;
    CheckRow r = report_row(ctx, "janssen_predicted_band_pressure", probe + " band " + std::to_string(b.index), b.measured,
                            "one band of one packing: the judged figure is the profile's mean ratio", predicted);
    r.error = (b.measured - predicted) / predicted;
    out.push_back(r);
  }
  const std::string sum_text =
      "sum of " + std::to_string(bands.size()) + " band pressures (" + pressure_column(spec) + ") over Janssen's with ";
  const std::string K_source = spec.contains("K_factor_source")
                                   ? "; K = " + std::to_string(K_factor) + " K_test: " + tolerance_source(spec, "K_factor", K_factor)
                                   : "";
  CheckRow profile = profile_row(spec, ctx, "janssen_predicted_profile", probe, profile_ratio(bands, c, K, mu),
                                 std::min(K.realisations, mu.realisations), K_source);
  profile.note = sum_text + parameters_text(K, mu, c.gamma);
  out.insert(out.begin(), profile);
  if (en_route) {
    // The same profile with EN 1991-4's K = 1.1 (1 − sin φ_i) from the shear test in place of K_o.
    const MeasuredParameter K_en = en_K_from_phi(phi);
    CheckRow en = profile_row(spec, ctx, "janssen_predicted_profile_en_K", probe, profile_ratio(bands, c, K_en, mu),
                              std::min(K_en.realisations, mu.realisations),
                              "; K = 1.1 (1 - sin phi_i), EN 1991-4:2006 5.2.1 and Annex C (docs/theory.md 5)");
    en.note = sum_text + parameters_text(K_en, mu, c.gamma);
    out.insert(out.begin() + 1, en);
  }
  if (spec.contains("floor_probe")) {
    // The floor carries σ_v at the base: Janssen's p_h(z_floor)/K.
    const std::string floor = spec.at("floor_probe");
    const CsvTable f = ctx.result.probe(floor);
    double force = 0.0, floor_area = 0.0;
    for (std::size_t i = 0; i < f.size(); ++i)
      force += f.number(i, "pressure_final") * f.number(i, "area"), floor_area += f.number(i, "area");
    const double depth = c.z_top - c.z_floor;
    const JanssenPoint j = janssen_point(c.gamma, c.D, K.mean, mu.mean, depth);
    const double pv = j.p / K.mean;
    // σ_v = p/K: d/dK (p/K) = (dp/dK − p/K)/K, d/dμ = (dp/dμ)/K.
    const double s = std::hypot((j.dp_dK - pv) / K.mean * K.scatter, j.dp_dmu / K.mean * mu.scatter) / pv;
    // Reported: Janssen's σ_v is uniform over the section, the floor sees its mean, and how far the
    // two differ (the distribution of σ_v that wall friction makes) is what the row measures.
    CheckRow r = report_row(ctx, "janssen_predicted_floor_stress", floor, force / c.area,
                            "Janssen's uniform sigma_v over the section, an assumption this row measures: no tolerance "
                            "covers it",
                            pv);
    r.error = (r.measured - pv) / pv;
    r.note = "the floor's vertical force over the column's section (" + std::to_string(floor_area / c.area) +
             " of it covered by the floor probe), against Janssen's p_h/K at depth " + std::to_string(depth) +
             " m; the material tests' scatter alone moves it by " + std::to_string(spec.value("coverage", 2.0) * s) + " (coverage x)";
    out.push_back(r);
  }
  return out;
}

}  // namespace harness
