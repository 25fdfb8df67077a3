#include "harness/variants.hpp"

#include "silodem/case/case_error.hpp"

namespace harness {

using nlohmann::json;

std::vector<Variant> expand_variants(const json& case_json, const std::string& section) {
  json base = case_json;
  std::vector<Variant> out{{"base", {}, base}};
  if (!case_json.contains(section) || !case_json[section].contains("variants")) return out;
  const json& axes = case_json[section]["variants"];
  if (!axes.is_object()) throw silodem::CaseError("$." + section + ".variants", "expected an object of axes");
  if (axes.empty()) return out;
  for (auto axis = axes.begin(); axis != axes.end(); ++axis) {
    const std::string path = "$." + section + ".variants." + axis.key();
    if (!axis->is_object() || axis->empty())
      throw silodem::CaseError(path, "expected a non-empty object {value label: merge patch}");
    std::vector<Variant> next;
    for (const auto& v : out) {
      for (auto value = axis->begin(); value != axis->end(); ++value) {
        if (!value->is_object()) throw silodem::CaseError(path + "." + value.key(), "a patch must be an object");
        if (value->contains("verify") || value->contains("compare"))
          throw silodem::CaseError(path + "." + value.key(), "a patch may not change \"verify\" or \"compare\"");
        Variant w = v;
        w.case_json.merge_patch(*value);
        w.axes.emplace_back(axis.key(), value.key());
        next.push_back(std::move(w));
      }
    }
    out = std::move(next);
  }
  for (auto& v : out) {
    v.label.clear();
    for (const auto& [a, val] : v.axes) v.label += (v.label.empty() ? "" : ",") + a + "=" + val;
  }
  return out;
}

std::string label_without(const Variant& v, const std::string& axis) {
  std::string out;
  for (const auto& [a, val] : v.axes)
    if (a != axis) out += (out.empty() ? "" : ",") + a + "=" + val;
  return out.empty() ? "base" : out;
}

}  // namespace harness
