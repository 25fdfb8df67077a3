#include "harness/angle_of_repose.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "silodem/output/state_file.hpp"

namespace harness {

using nlohmann::json;

HeapProfile heap_profile(const std::vector<silodem::BallSpec>& balls, double axis_x, double axis_y, double bin_width) {
  double foot = INFINITY;
  for (const auto& b : balls)
    if (!b.fixed) foot = std::min(foot, b.position.z() - b.radius);
  std::vector<double> top;
  for (const auto& b : balls) {
    if (b.fixed) continue;
    const double r = std::hypot(b.position.x() - axis_x, b.position.y() - axis_y);
    const auto bin = std::size_t(r / bin_width);
    if (bin >= top.size()) top.resize(bin + 1, NAN);
    const double h = b.position.z() + b.radius - foot;
    if (!(top[bin] >= h)) top[bin] = h;
  }
  HeapProfile p;
  for (std::size_t k = 0; k < top.size(); ++k)
    if (std::isfinite(top[k])) p.r.push_back((double(k) + 0.5) * bin_width), p.height.push_back(top[k]);
  return p;
}

SlopeFit heap_slope(const HeapProfile& p, double fit_from, double fit_to) {
  SlopeFit f;
  if (p.height.empty()) return f;
  const double peak = *std::max_element(p.height.begin(), p.height.end());
  std::size_t k = std::size_t(std::max_element(p.height.begin(), p.height.end()) - p.height.begin());
  double n = 0, sr = 0, sh = 0, srr = 0, srh = 0, shh = 0;
  for (; k < p.height.size() && p.height[k] >= fit_from * peak; ++k) {
    if (p.height[k] > fit_to * peak) continue;
    const double r = p.r[k], h = p.height[k];
    n += 1, sr += r, sh += h, srr += r * r, srh += r * h, shh += h * h;
  }
  f.bins = int(n);
  if (n < 3) return f;
  const double cov = srh - sr * sh / n, var_r = srr - sr * sr / n, var_h = shh - sh * sh / n;
  const double slope = cov / var_r;
  f.angle_deg = std::atan(-slope) * 180.0 / std::numbers::pi;
  f.r2 = var_h > 0.0 ? cov * cov / (var_r * var_h) : NAN;
  return f;
}

void validate_angle_of_repose(const silodem::JsonReader& r, const silodem::CaseConfig& cfg) {
  const std::string wall = r.string("axis_wall");
  bool found = false;
  for (const auto& w : cfg.walls) found = found || (w.name == wall && w.type == "cylinder");
  if (!found) r.fail("axis_wall", "no cylinder wall named \"" + wall + "\"");
  const double from = r.has("fit_from") ? r.number("fit_from") : 0.25, to = r.has("fit_to") ? r.number("fit_to") : 0.75;
  if (!(from > 0.0 && from < to && to < 1.0)) r.fail("fit_to", "need 0 < fit_from < fit_to < 1 (fractions of the heap's height)");
  if (r.has("bin_width") && !(r.number("bin_width") > 0.0)) r.fail("bin_width", "must be > 0 (m)");
}

std::vector<CheckRow> angle_of_repose(const json& spec, const RunContext& ctx) {
  const std::string wall = spec.at("axis_wall");
  silodem::Vec3 axis = silodem::Vec3::Zero();
  for (const auto& w : ctx.cfg.walls)
    if (w.name == wall) axis = w.centre;
  double largest_grain = 0.0;
  for (const auto& b : ctx.cfg.balls)
    if (!b.fixed) largest_grain = std::max(largest_grain, 2.0 * b.radius);
  const double width = spec.value("bin_width", largest_grain);
  const auto state = silodem::read_state(ctx.result.dir / "state.sds");
  const HeapProfile p = heap_profile(state.balls, axis.x(), axis.y(), width);
  const SlopeFit f = heap_slope(p, spec.value("fit_from", 0.25), spec.value("fit_to", 0.75));
  const bool ok = std::isfinite(f.angle_deg);
  CheckRow row = report_row(ctx, "angle_of_repose_deg", "heap about " + wall, f.angle_deg,
                            ok ? "a material parameter measured by a virtual test (EN 1991-4 Annex C lists it): no "
                                 "oracle; its scatter over packings is the spread row"
                               : "fewer than three radial bins on the heap's slope: no heap at rest to measure");
  const double peak = p.height.empty() ? NAN : *std::max_element(p.height.begin(), p.height.end());
  row.note = "line fitted to the surface over " + std::to_string(f.bins) + " radial bins of " + std::to_string(width) +
             " m (R^2 " + std::to_string(f.r2) + "), heap height " + std::to_string(peak) + " m";
  return {row};
}

}  // namespace harness
