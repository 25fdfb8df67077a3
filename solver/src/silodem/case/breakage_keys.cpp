#include "silodem/case/breakage_keys.hpp"

#include <string>

#include "silodem/case/contact_keys.hpp"
#include "silodem/case/limits.hpp"

namespace silodem::case_keys {

namespace {
constexpr double kEnergy = 1e12;  // J: any breakage energy of a grain
}

BreakageSpec read_breakage(const JsonReader& r, const CaseConfig& cfg) {
  BreakageSpec b;
  if (cfg.contact.normal != NormalModel::Hertz)
    r.fail("materials", "breakage is built on Hertz contacts (seed 003's law): set contact.normal to \"hertz\"");
  if (cfg.contact.cohesion) r.fail("materials", "breakage does not run with the paper's cohesion");
  const nlohmann::json& ms = r.array("materials");
  require(!ms.empty(), r, "materials", "name at least one breakable material");
  for (std::size_t i = 0; i < ms.size(); ++i) {
    const std::string path = r.child_path("materials") + "[" + std::to_string(i) + "]";
    if (!ms[i].is_string()) throw CaseError(path, "expected a material name (string)");
    const std::string name = ms[i].get<std::string>();
    if (!cfg.materials.count(name)) throw CaseError(path, "no material named \"" + name + "\"");
    b.materials.push_back(name);
  }
  b.minimum_energy = r.number_in("minimum_energy", 0.0, kEnergy, "J");
  b.strength = positive(r, "strength", kEnergy, "1/J");
  b.size_exponent = r.number_in_or("size_exponent", 0.0, 10.0, "", 0.0);
  b.smallest_ratio = r.number_in_or("smallest_ratio", 0.0, 1.0, "", 0.5);
  if (const auto c = r.opt_object("fragments")) {
    b.count_mean = c->number_in_or("mean", 2.0, 1000.0, "", b.count_mean);
    b.count_sd = c->number_in_or("sd", 0.0, 1000.0, "", b.count_sd);
    b.count_min = int(c->integer_in_or("min", 2, 1000, b.count_min));
    b.count_max = int(c->integer_in_or("max", 2, 1000, b.count_max));
    require(b.count_min <= b.count_max, *c, "max", "must be >= min");
    c->finish();
  }
  b.secant_energy = r.choice_or("energy", {"hertz", "secant"}, "hertz") == "secant";
  b.wall_contacts = r.boolean_or("wall_contacts", true);
  b.from_time = r.number_in_or("from_time", 0.0, 1e9, "s", 0.0);
  r.finish();
  return b;
}

}  // namespace silodem::case_keys
