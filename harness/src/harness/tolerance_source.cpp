#include "harness/tolerance_source.hpp"

#include <cstdio>

namespace harness {

using nlohmann::json;

std::string source_key(const std::string& key) { return key + "_source"; }

void validate_tolerance_source(const silodem::JsonReader& r, const std::string& key) {
  const std::string k = source_key(key);
  if (!r.has(k)) return;
  if (!r.raw(k).is_object()) r.fail(k, "an object {\"type\": \"scheme_bound\" | \"seed_scatter\" | \"published\", ...}");
  const silodem::JsonReader s = r.object(k);
  const std::string type = s.choice_or("type", {"scheme_bound", "seed_scatter", "published"}, "");
  const auto text = [&](const char* field) {
    if (s.string(field).find_first_not_of(" \t\n") == std::string::npos) s.fail(field, "must say it (not empty)");
  };
  if (type.empty()) s.fail("type", "give \"scheme_bound\", \"seed_scatter\" or \"published\"");
  if (type == "scheme_bound") text("derivation");
  if (type == "published") text("citation");
  if (type == "seed_scatter") {
    if (s.integer("realisations") < 2) s.fail("realisations", "a scatter needs at least 2 realisations");
    if (!(s.number("scatter") > 0.0)) s.fail("scatter", "must be > 0 (on the scale of the tolerance)");
    if (s.has("measured")) text("measured");
  }
  s.finish();
}

std::string tolerance_source(const json& spec, const std::string& key, double tolerance) {
  const std::string k = source_key(key);
  if (!spec.is_object() || !spec.contains(k)) return "";
  const json& s = spec.at(k);
  const std::string type = s.at("type");
  if (type == "scheme_bound") return "scheme bound: " + s.at("derivation").get<std::string>();
  if (type == "published") return "published: " + s.at("citation").get<std::string>();
  const double scatter = s.at("scatter").get<double>();
  char b[200];
  std::snprintf(b, sizeof b, "seed scatter %.3g over %ld realisations (tolerance = %.3g x scatter)", scatter,
                s.at("realisations").get<long>(), tolerance / scatter);
  std::string out = b;
  if (s.contains("measured")) out += "; measured: " + s.at("measured").get<std::string>();
  return out;
}

}  // namespace harness
