#include "harness/profile_check.hpp"

#include <cmath>
#include <map>

#include "silodem/case/json_reader.hpp"

namespace harness {

void validate_pressure_profile(const silodem::JsonReader& r, const silodem::CaseConfig& cfg) {
  const std::string name = r.string("wall_probe");
  bool found = false;
  for (const auto& p : cfg.probes) found = found || (p.name == name && p.type == "wall_pressure");
  if (!found) r.fail("wall_probe", "no wall_pressure probe named \"" + name + "\"");
  (void)r.choice_or("value", {"mean", "final"}, "mean");
}

std::vector<CheckRow> pressure_profile(const nlohmann::json& spec, const RunContext& ctx) {
  const std::string probe = spec.at("wall_probe");
  const std::string column = "pressure_" + spec.value("value", std::string("mean"));
  const CsvTable t = ctx.result.probe(probe);
  // Band pressure = Σ cell pressure·area / Σ area: the band's total normal force over its area.
  std::map<int, std::pair<double, double>> band;
  for (std::size_t i = 0; i < t.size(); ++i) {
    auto& b = band[int(t.number(i, "height_bin"))];
    b.first += t.number(i, column) * t.number(i, "area");
    b.second += t.number(i, "area");
  }
  std::vector<CheckRow> out;
  for (const auto& [h, v] : band) {
    CheckRow r;
    r.case_name = ctx.cfg.name;
    r.variant = ctx.variant;
    r.code = ctx.code;
    r.quantity = "band_pressure";
    r.subject = probe + " band " + std::to_string(h);
    r.measured = v.first / v.second;
    r.expected = NAN;
    r.error = NAN;
    r.pass = std::isfinite(r.measured) && r.measured >= 0.0;
    r.note = spec.value("value", std::string("mean")) + " pressure, Pa, averaged over the angle (0 = bottom / outlet end)";
    out.push_back(r);
  }
  return out;
}

}  // namespace harness
