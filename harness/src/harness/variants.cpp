#include "harness/variants.hpp"

#include <cmath>
#include <map>

#include "silodem/case/case_error.hpp"
#include "silodem/case/case_loader.hpp"
#include "silodem/case/limits.hpp"
#include "silodem/case/memory_estimate.hpp"
#include "silodem/case/path_name.hpp"

namespace harness {

using nlohmann::json;

namespace {

/// An axis or value name: it becomes part of the variant's directory name, and ',' and '='
/// write its label ("axis=value,axis=value"), so they may not appear in it.
void require_variant_name(const std::string& name, const std::string& path) {
  silodem::require_path_name(name, path);
  if (name.find_first_of(",=") != std::string::npos)
    throw silodem::CaseError(path, "the name \"" + name + "\" may not contain ',' or '=' (they separate the axes "
                                   "and values of a variant's label)");
}

/// Every axis well formed and named, and the product of their sizes at most limits::kVariantRuns
/// (checked before any variant is built). Returns that product.
double check_axes(const json& axes, const std::string& section) {
  double runs = 1.0;
  for (auto axis = axes.begin(); axis != axes.end(); ++axis) {
    const std::string path = "$." + section + ".variants." + axis.key();
    if (!axis->is_object() || axis->empty())
      throw silodem::CaseError(path, "expected a non-empty object {value label: merge patch}");
    require_variant_name(axis.key(), path);
    for (auto value = axis->begin(); value != axis->end(); ++value) {
      if (!value->is_object()) throw silodem::CaseError(path + "." + value.key(), "a patch must be an object");
      if (value->contains("verify") || value->contains("compare"))
        throw silodem::CaseError(path + "." + value.key(), "a patch may not change \"verify\" or \"compare\"");
      require_variant_name(value.key(), path + "." + value.key());
    }
    runs *= double(axis->size());
  }
  if (runs > silodem::limits::kVariantRuns)
    throw silodem::CaseError("$." + section + ".variants",
                             "the axes make " + std::to_string(std::llround(runs)) + " runs, more than the " +
                                 std::to_string(std::llround(silodem::limits::kVariantRuns)) + " one case may make");
  return runs;
}

/// verify and compare hold every variant, as its JSON and as its loaded case (which keeps its own
/// copy), before the first run: that must fit beside a run.
void check_held_copies(const json& case_json, double runs, const std::string& section) {
  const double bytes = runs * 2.0 * silodem::json_heap_bytes(case_json);
  const silodem::MemoryLimit limit = silodem::run_memory_limit();
  if (bytes > 0.5 * limit.bytes)
    throw silodem::CaseError("$." + section + ".variants",
                             "the " + std::to_string(std::llround(runs)) + " variants would hold " +
                                 silodem::format_bytes(bytes) + " of copies of this case before the first run, more "
                                 "than half of " + limit.source + ": fewer variants, or a smaller case");
}

/// Distinct variants must get distinct directories, each a name the filesystem takes.
void check_directories(const std::vector<Variant>& variants, const std::string& section) {
  std::map<std::string, std::string> seen;  // directory name → label
  for (const auto& v : variants) {
    const std::string dir = variant_dir_name(v);
    if (dir.size() > 2 * silodem::limits::kNameBytes)
      throw silodem::CaseError("$." + section + ".variants",
                               "the variant " + v.label + " would write to a directory name of " +
                                   std::to_string(dir.size()) + " bytes (at most " +
                                   std::to_string(2 * silodem::limits::kNameBytes) + "): shorten its axis or value names");
    const auto [it, fresh] = seen.emplace(dir, v.label);
    if (!fresh)
      throw silodem::CaseError("$." + section + ".variants", "the variants " + it->second + " and " + v.label +
                                                                 " would write to the same directory \"" + dir + "\"");
  }
}

}  // namespace

std::vector<Variant> expand_variants(const json& case_json, const std::string& section) {
  json base = case_json;
  std::vector<Variant> out{{"base", {}, base}};
  if (!case_json.contains(section) || !case_json[section].contains("variants")) return out;
  const json& axes = case_json[section]["variants"];
  if (!axes.is_object()) throw silodem::CaseError("$." + section + ".variants", "expected an object of axes");
  if (axes.empty()) return out;
  check_held_copies(case_json, check_axes(axes, section), section);
  for (auto axis = axes.begin(); axis != axes.end(); ++axis) {
    std::vector<Variant> next;
    for (const auto& v : out) {
      for (auto value = axis->begin(); value != axis->end(); ++value) {
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
  check_directories(out, section);
  return out;
}

std::string variant_dir_name(const Variant& v) {
  std::string s = v.label;
  for (char& c : s)
    if (c == ',') c = '_';
    else if (c == ' ') c = '-';
  return s;
}

std::string label_without(const Variant& v, const std::string& axis) {
  std::string out;
  for (const auto& [a, val] : v.axes)
    if (a != axis) out += (out.empty() ? "" : ",") + a + "=" + val;
  return out.empty() ? "base" : out;
}

silodem::CaseConfig load_variant(const Variant& v, const std::string& what) {
  try {
    return silodem::load_case(v.case_json);
  } catch (const silodem::CaseError& e) {
    throw silodem::CaseError(e.path(), std::string(e.what()).substr(e.path().size() + 2) + " (in " + what + " " + v.label + ")");
  }
}

std::vector<std::string> variant_axes(const std::vector<Variant>& variants) {
  std::vector<std::string> axes;
  for (const auto& [axis, value] : variants.front().axes) axes.push_back(axis);
  return axes;
}

}  // namespace harness
