#include "harness/tray_checks.hpp"

#include <cmath>
#include <stdexcept>

namespace harness {

using nlohmann::json;

namespace {
const silodem::WallSpec& tray_named(const silodem::CaseConfig& cfg, const std::string& name) {
  for (const auto& w : cfg.walls)
    if (w.name == name && w.type == "tray") return w;
  throw std::runtime_error("no tray " + name);
}
}  // namespace

std::vector<CheckRow> slot_discharge(const json& spec, const RunContext& ctx) {
  const silodem::WallSpec& tray = tray_named(ctx.cfg, spec.at("tray"));
  const std::string probe = spec.at("outflow_probe");
  const double from = spec.value("from_time", 0.0);
  const double end = ctx.result.summary.at("run").at("time").get<double>();
  const CsvTable exits = ctx.result.probe(probe);
  std::vector<double> mass(tray.slots.size(), 0.0), late(tray.slots.size(), 0.0);
  for (std::size_t i = 0; i < exits.size(); ++i) {
    const double x = exits.number(i, "x") - tray.centre.x();
    std::size_t nearest = 0;
    for (std::size_t k = 1; k < tray.slots.size(); ++k)
      if (std::abs(x - tray.slots[k].x) < std::abs(x - tray.slots[nearest].x)) nearest = k;
    mass[nearest] += exits.number(i, "mass");
    if (exits.number(i, "t") >= from) late[nearest] += exits.number(i, "mass");
  }
  std::vector<CheckRow> out;
  const std::string why = "the seed reports the tray's discharge only qualitatively; no published law for a horizontally vibrated slot";
  for (std::size_t k = 0; k < tray.slots.size(); ++k) {
    const std::string subject = "slot x=" + std::to_string(tray.slots[k].x);
    CheckRow r = report_row(ctx, "slot_mass_rate", subject, end > from ? late[k] / (end - from) : NAN, why);
    r.note = std::to_string(mass[k]) + " kg through it in all";
    out.push_back(r);
  }
  long grains = 0;
  for (const auto& b : ctx.cfg.balls) grains += !b.fixed;
  const long left = ctx.result.summary.at("balls").at("mobile").get<long>();
  out.push_back(match_row(ctx, "grain_count", probe, double(grains), double(long(exits.size()) + left), 0.0,
                          "exact: a grain is in the tray or counted out", false));
  const double gamma = tray.motion ? tray.motion->amplitude * std::pow(2.0 * M_PI * tray.motion->frequency, 2) /
                                         ctx.cfg.gravity.norm()
                                   : 0.0;
  out.push_back(report_row(ctx, "vibration_gamma", tray.name, gamma, "the run's set vibration: A (2 pi f)^2 / g"));
  return out;
}

void validate_tray_check(const silodem::JsonReader& r, const silodem::CaseConfig& cfg) {
  const std::string probe = r.string("outflow_probe");
  bool found = false;
  for (const auto& p : cfg.probes) found = found || (p.name == probe && p.type == "outflow");
  if (!found) r.fail("outflow_probe", "no outflow probe named \"" + probe + "\"");
  const std::string tray = r.string("tray");
  bool is_tray = false;
  for (const auto& w : cfg.walls) is_tray = is_tray || (w.name == tray && w.type == "tray" && !w.slots.empty());
  if (!is_tray) r.fail("tray", "no tray with slots named \"" + tray + "\"");
  if (r.has("from_time") && !(r.number("from_time") >= 0.0)) r.fail("from_time", "must be >= 0");
  // The grain count is the listed mobile balls': drops and fragments would add to it.
  if (cfg.drops) r.fail("type", "the grain count takes the listed balls; the case adds drops");
  if (cfg.breakage) r.fail("type", "the grain count takes the listed balls; breakage adds fragments");
  r.finish();
}

}  // namespace harness
