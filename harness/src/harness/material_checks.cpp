#include "harness/material_checks.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>

namespace harness {

using nlohmann::json;

namespace {
const char* kMeasured =
    "a material parameter measured by a virtual test (EN 1991-4 Annex C): no oracle; the Janssen prediction takes "
    "it, with its scatter over packings (the spread rows)";
}  // namespace

void validate_mantle_band_check(const silodem::JsonReader& r, const silodem::CaseConfig& cfg) {
  const std::string probe = r.string("wall_probe");
  bool found = false;
  for (const auto& p : cfg.probes)
    if (p.name == probe && p.type == "wall_pressure")
      for (const auto& w : cfg.walls) found = found || (w.name == p.wall && w.type == "cylinder");
  if (!found) r.fail("wall_probe", "no wall_pressure probe named \"" + probe + "\" on a cylinder");
  for (const char* k : {"exclude_bottom_diameters", "exclude_top_diameters"})
    if (r.has(k) && !(r.number(k) >= 0.0)) r.fail(k, "must be >= 0");
}

ColumnInWall column_in_wall(const std::string& probe, const RunContext& ctx) {
  const json& d = ctx.result.probe_digest(probe);
  ColumnInWall c;
  c.probe = ctx.result.probe(probe);
  c.D = d.at("geometry").at("diameter"), c.H = d.at("geometry").at("height");
  c.z_base = d.at("geometry").at("centre")[2], c.z_floor = column_floor(ctx.cfg, d.at("geometry"));
  const json& fill = ctx.result.summary.at("fill");
  c.z_top = fill.at("z_top").get<double>(), c.mass = fill.at("mobile_mass").get<double>();
  c.area = std::numbers::pi * 0.25 * c.D * c.D;
  c.gamma = c.mass * ctx.cfg.gravity.norm() / (c.area * (c.z_top - c.z_floor));
  return c;
}

std::vector<CheckRow> lateral_pressure_ratio(const json& spec, const RunContext& ctx) {
  const std::string probe = spec.at("wall_probe");
  const ColumnInWall c = column_in_wall(probe, ctx);
  const CsvTable& t = c.probe;
  const double D = c.D, z_top = c.z_top, mass = c.mass, area = c.area, gamma = c.gamma, g = ctx.cfg.gravity.norm();
  // Per height band (final state, at rest): the angle-averaged horizontal pressure, and the
  // vertical force the wall carries there (its shear, down-slope on a cylinder, times the area).
  std::map<int, std::pair<double, int>> pressure;
  std::map<int, double> carried;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const int h = int(t.number(i, "height_bin"));
    pressure[h].first += t.number(i, "pressure_final");
    ++pressure[h].second;
    carried[h] += t.number(i, "shear_final") * t.number(i, "area");
  }
  const int bins = int(pressure.size());
  const double lo = c.z_floor + spec.value("exclude_bottom_diameters", 0.5) * D;
  const double hi = z_top - spec.value("exclude_top_diameters", 0.5) * D;
  // Slice equilibrium of the column above height z (at rest): σ_v(z) A = γ A (z_top − z) − S(z),
  // S the vertical force on the wall above z (half of z's own band).
  double above = 0.0, sum_k = 0.0, sigma_min = INFINITY, sigma_max = 0.0;
  int used = 0;
  for (int h = bins - 1; h >= 0; --h) {
    const double z_mid = c.band_mid(h, bins);
    const double sigma_v = gamma * std::max(0.0, z_top - z_mid) - (above + 0.5 * carried[h]) / area;
    above += carried[h];
    if (z_mid < lo || z_mid > hi || !(sigma_v > 0.0)) continue;
    sum_k += pressure[h].first / pressure[h].second / sigma_v;
    sigma_min = std::min(sigma_min, sigma_v), sigma_max = std::max(sigma_max, sigma_v);
    ++used;
  }
  std::vector<CheckRow> out;
  CheckRow k = report_row(ctx, "lateral_pressure_ratio_K", probe, used ? sum_k / used : NAN,
                          used ? kMeasured : "no band of the mantle lies in the column between the excluded ends");
  k.note = "mean of p_h/sigma_v over " + std::to_string(used) + " bands, sigma_v " + std::to_string(sigma_min) + "-" +
           std::to_string(sigma_max) + " Pa (slice equilibrium, gamma = " + std::to_string(gamma) + " N/m^3)";
  out.push_back(k);
  CheckRow w = report_row(ctx, "wall_carried_fraction", probe, above / (mass * g),
                          "what the frictionless wall's roughness carries of the weight: taken out of sigma_v, reported");
  out.push_back(w);
  return out;
}

std::vector<CheckRow> wall_friction(const json& spec, const RunContext& ctx) {
  const std::string probe = spec.at("wall_probe");
  const ColumnInWall c = column_in_wall(probe, ctx);
  const CsvTable& t = c.probe;
  const double D = c.D, z_top = c.z_top;
  // Per height band of the wall's own frame: the time means of Σ F·n and of Σ F·t (t down the wall:
  // a rising wall is pulled down by the grains it slides past) over the probe's window.
  std::map<int, std::pair<double, double>> band;  // normal force, shear force
  for (std::size_t i = 0; i < t.size(); ++i) {
    auto& b = band[int(t.number(i, "height_bin"))];
    b.first += t.number(i, "pressure_mean") * t.number(i, "area");
    b.second += t.number(i, "shear_mean") * t.number(i, "area");
  }
  const int bins = int(band.size());
  const double lo = c.z_floor + spec.value("exclude_bottom_diameters", 0.5) * D;
  const double hi = z_top - spec.value("exclude_top_diameters", 0.5) * D;
  double normal = 0.0, shear = 0.0, band_min = INFINITY, band_max = -INFINITY;
  int used = 0;
  for (int h = 0; h < bins; ++h) {
    const double z_mid = c.band_mid(h, bins);
    const auto [n, s] = band[h];
    if (z_mid < lo || z_mid > hi || !(n > 0.0)) continue;
    normal += n, shear += s, ++used;
    band_min = std::min(band_min, s / n), band_max = std::max(band_max, s / n);
  }
  CheckRow mu = report_row(ctx, "wall_friction_mu_w", probe, used ? shear / normal : NAN,
                           used ? kMeasured : "no band of the mantle lies in the column between the excluded ends");
  mu.note = "sum tau / sum p over " + std::to_string(used) + " bands (band ratios " + std::to_string(band_min) + " to " +
            std::to_string(band_max) + "), mean normal force " + std::to_string(used ? normal / used : 0.0) + " N per band";
  return {mu};
}

namespace {
/// The move_wall event that sets `wall` moving sideways (the first one with a velocity).
const silodem::StageEvent* shear_event(const silodem::CaseConfig& cfg, const std::string& wall) {
  for (const auto& e : cfg.events)
    if (e.type == "move_wall" && e.wall == wall && e.ball.empty() && e.velocity.norm() > 0.0) return &e;
  return nullptr;
}
}  // namespace

void validate_direct_shear(const silodem::JsonReader& r, const silodem::CaseConfig& cfg) {
  const std::string probe = r.string("section_probe");
  bool found = false;
  for (const auto& p : cfg.probes) found = found || (p.name == probe && p.type == "section_force");
  if (!found) r.fail("section_probe", "no section_force probe named \"" + probe + "\"");
  const silodem::StageEvent* e = shear_event(cfg, r.string("moving_wall"));
  if (!e) r.fail("moving_wall", "no move_wall event sets this wall moving");
  if (std::abs(e->velocity.z()) > 1e-9 * e->velocity.norm())
    r.fail("moving_wall", "the shear must be horizontal (the event's velocity has a z component)");
  if (r.has("smoothing") && !(r.number("smoothing") > 0.0)) r.fail("smoothing", "must be > 0 (m of travel)");
  if (r.has("critical_from") && !(r.number("critical_from") > 0.0 && r.number("critical_from") < 1.0))
    r.fail("critical_from", "must lie in (0, 1): the fraction of the travel after which the state is critical");
}

std::vector<CheckRow> direct_shear(const json& spec, const RunContext& ctx) {
  const std::string probe = spec.at("section_probe");
  const silodem::StageEvent& e = *shear_event(ctx.cfg, spec.at("moving_wall"));
  const double speed = e.velocity.norm();
  const silodem::Vec3 dir = e.velocity / speed;
  const CsvTable t = ctx.result.probe(probe);
  // Along the travel s = v (t − t_0): τ = −F·ŝ (the material below holds the body above back) and
  // σ = F_z, F the force across the plane on the body above.
  std::vector<double> s, ratio, sigma;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double ti = t.number(i, "t");
    if (ti <= e.time) continue;
    const silodem::Vec3 f(t.number(i, "fx"), t.number(i, "fy"), t.number(i, "fz"));
    s.push_back(speed * (ti - e.time)), ratio.push_back(-f.dot(dir) / f.z()), sigma.push_back(f.z());
  }
  const double travel = s.empty() ? 0.0 : s.back();
  const double window = spec.value("smoothing", 0.002), critical_from = spec.value("critical_from", 0.5);
  // Peak: the largest running mean over `window` of travel; critical state: the mean past critical_from.
  double peak = NAN, peak_at = NAN, crit = 0.0, crit_sq = 0.0, sigma_mean = 0.0;
  int n_crit = 0;
  std::size_t lo = 0;
  double run = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    run += ratio[i];
    while (s[i] - s[lo] > window) run -= ratio[lo++];
    const double mean = run / double(i - lo + 1);
    if (s[i] >= window && !(mean <= peak)) peak = mean, peak_at = s[i] - 0.5 * window;
    if (s[i] >= critical_from * travel) crit += ratio[i], crit_sq += ratio[i] * ratio[i], sigma_mean += sigma[i], ++n_crit;
  }
  const bool ok = n_crit > 1 && std::isfinite(peak);
  const std::string why = ok ? kMeasured : "the probe has no rows along the shear (did the run reach it?)";
  crit = ok ? crit / n_crit : NAN;
  const double sd = ok ? std::sqrt(std::max(0.0, crit_sq / n_crit - crit * crit)) : NAN;
  const auto deg = [](double mu) { return std::atan(mu) * 180.0 / std::numbers::pi; };
  std::vector<CheckRow> out;
  CheckRow p = report_row(ctx, "internal_friction_peak_deg", probe, deg(peak), why);
  p.note = "tan phi = tau/sigma = " + std::to_string(peak) + " (running mean over " + std::to_string(window) +
           " m), at travel " + std::to_string(peak_at) + " m of " + std::to_string(travel) + " m";
  out.push_back(p);
  CheckRow c = report_row(ctx, "internal_friction_critical_deg", probe, deg(crit), why);
  c.note = "tan phi = " + std::to_string(crit) + " +/- " + std::to_string(sd) + " (sd of " + std::to_string(n_crit) +
           " rows past " + std::to_string(critical_from * travel) + " m of travel), normal force " +
           std::to_string(ok ? sigma_mean / n_crit : NAN) + " N";
  out.push_back(c);
  return out;
}

}  // namespace harness
