#pragma once
// A case's "verify.variants": named axes of JSON merge patches (RFC 7386) whose product gives the
// runs to make — e.g. integrator × clamp × time step — so a sweep is data, not code.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "silodem/case/case_config.hpp"

namespace harness {

struct Variant {
  std::string label;                       // "axis=value,axis=value" ("base" without axes)
  std::vector<std::pair<std::string, std::string>> axes;  // (axis, value) in axis order
  nlohmann::json case_json;                // the case with every patch applied
};

/// Expands `<section>.variants` ("verify" or "compare"). Throws silodem::CaseError naming the JSON
/// path for a malformed "variants" object, an axis or value name that cannot be part of a
/// directory name (silodem/case/path_name.hpp; nor ',' or '='), more than limits::kVariantRuns
/// runs, or two variants that would share a directory.
std::vector<Variant> expand_variants(const nlohmann::json& case_json, const std::string& section = "verify");

/// The variant's directory under <out>/<case name>/: its label with ',' as '_' and ' ' as '-'.
std::string variant_dir_name(const Variant& v);

/// The variant's case loaded; a CaseError names the variant ("(in <what> <label>)").
silodem::CaseConfig load_variant(const Variant& v, const std::string& what);

/// The axes of a case's variants, in their order.
std::vector<std::string> variant_axes(const std::vector<Variant>& variants);

/// The label with one axis removed (groups variants that differ only along that axis).
std::string label_without(const Variant& v, const std::string& axis);

}  // namespace harness
