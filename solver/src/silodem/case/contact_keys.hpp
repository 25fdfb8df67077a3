#pragma once
// The case file's contact keys (docs/case-format.md "Friction"): the sub-models of `contact`, a
// material's friction and Hertz constants, and `material_pairs`. Read by case_loader.cpp; apart
// so that the loader stays one concept a file.
#include <string>

#include "silodem/case/case_config.hpp"
#include "silodem/case/json_reader.hpp"
#include "silodem/case/json_text.hpp"

namespace silodem::case_keys {

inline void require(bool ok, const JsonReader& r, const std::string& key, const std::string& reason) {
  if (!ok) r.fail(key, reason);
}

/// A number in (0, hi]: zero and negatives get the plain "must be > 0", absurd sizes the range.
inline double positive(const JsonReader& r, const std::string& key, double hi, const std::string& unit) {
  const double v = r.number(key);
  require(v > 0.0, r, key, "must be > 0 (got " + format_number(v) + ")");
  return r.number_in(key, 0.0, hi, unit);
}

/// A key that only some sub-model reads: refused, with the reason, when the scene does not use it.
inline void refuse_unless(bool used, const JsonReader& r, const std::string& key, const std::string& needs) {
  if (!used && r.has(key)) r.fail(key, "is read only with " + needs + " (docs/case-format.md \"Friction\")");
}

/// The friction, rolling and shear constants of a material.
void read_friction(const JsonReader& r, Material& m, const ContactSpec& contact);
/// A material of the Hertz law: elastic constants and a restitution (or damping ratio).
Material read_hertz_material(const JsonReader& r, Material m, bool clamp);
/// The sub-models of contact: one keyword each, meaningless combinations refused with their path.
void read_contact_models(const JsonReader& c, ContactSpec& spec);
/// Grain–wall or grain–grain constants given for the pair itself.
void read_material_pairs(const JsonReader& r, CaseConfig& cfg);

}  // namespace silodem::case_keys
