#include "silodem/case/contact_keys.hpp"

#include <set>
#include <utility>

#include "silodem/case/limits.hpp"
#include "silodem/contact/hertz_constants.hpp"

namespace silodem::case_keys {

using nlohmann::json;

/// The friction, rolling and shear constants of a material (docs/case-format.md "Friction").
void read_friction(const JsonReader& r, Material& m, const ContactSpec& contact) {
  const TangentialModel t = contact.tangential;
  const bool history = t == TangentialModel::LinearHistory || t == TangentialModel::Mindlin;
  refuse_unless(t != TangentialModel::None, r, "friction", "a tangential law (contact.tangential)");
  refuse_unless(contact.rolling != RollingModel::None, r, "rolling_friction", "a rolling law (contact.rolling)");
  refuse_unless(t == TangentialModel::LinearHistory, r, "shear_stiffness_ratio", "contact.tangential \"linear_history\"");
  refuse_unless(history, r, "tangential_damping_ratio", "a history law (\"linear_history\", \"mindlin\")");
  refuse_unless(t == TangentialModel::CoulombSliding, r, "tangential_damping", "contact.tangential \"coulomb_sliding\"");
  refuse_unless(contact.rolling == RollingModel::Spring, r, "rolling_damping_ratio", "contact.rolling \"epsd\"");
  m.friction = r.number_in_or("friction", 0.0, limits::kFriction, "", 0.0);
  m.rolling_friction = r.number_in_or("rolling_friction", 0.0, limits::kFriction, "", 0.0);
  m.shear_stiffness_ratio = r.number_in_or("shear_stiffness_ratio", 0.0, limits::kFactor, "", 2.0 / 7.0);
  m.tangential_damping_ratio = r.number_in_or("tangential_damping_ratio", 0.0, limits::kFactor, "", 0.0);
  m.tangential_damping = r.number_in_or("tangential_damping", 0.0, limits::kDamping, "N s/m", 0.0);
  m.rolling_damping_ratio = r.number_in_or("rolling_damping_ratio", 0.0, limits::kFactor, "", 0.0);
}

/// A material of the Hertz law: elastic constants and a restitution (or damping ratio) instead of
/// the paper's per-ball k_i, c_i (docs/model.md §10.3).
Material read_hertz_material(const JsonReader& r, Material m, bool clamp) {
  for (const char* key : {"stiffness", "contact_time", "damping", "reference_radius"})
    if (r.has(key)) r.fail(key, "is a constant of the linear law; a Hertz material gives \"youngs_modulus\" and \"poisson_ratio\"");
  m.youngs_modulus = positive(r, "youngs_modulus", limits::kModulus, "Pa");
  m.poisson_ratio = r.number_in("poisson_ratio", -0.99, 0.5, "");
  const bool has_z = r.has("damping_ratio"), has_e = r.has("restitution");
  if (has_z == has_e) r.fail("", "give exactly one of \"damping_ratio\" or \"restitution\"");
  if (has_z) {
    m.hertz_damping_ratio = r.number_in("damping_ratio", 0.0, limits::kDampingRatio, "");
    m.derived_from = "youngs_modulus+damping_ratio";
  } else {
    const double e = r.number("restitution");
    require(e > 0.0 && e <= 1.0, r, "restitution", "must be in (0, 1]");
    m.hertz_damping_ratio = contact::hertz_damping_ratio_for_restitution(e, clamp);
    m.derived_from = "youngs_modulus+restitution";
  }
  r.finish();
  return m;
}

/// The sub-models of contact (docs/model.md §10): one keyword each, and the combinations that mean
/// nothing refused with their path.
void read_contact_models(const JsonReader& c, ContactSpec& spec) {
  const std::string normal = c.choice_or("normal", {"linear", "hertz"}, "linear");
  const std::string tangential = c.choice_or("tangential", {"none", "coulomb_sliding", "linear_history", "mindlin"}, "none");
  const std::string rolling = c.choice_or("rolling", {"none", "constant_torque", "epsd"}, "none");
  spec.normal = normal == "hertz" ? NormalModel::Hertz : NormalModel::Linear;
  spec.tangential = tangential == "coulomb_sliding"  ? TangentialModel::CoulombSliding
                    : tangential == "linear_history" ? TangentialModel::LinearHistory
                    : tangential == "mindlin"        ? TangentialModel::Mindlin
                                                     : TangentialModel::None;
  spec.rolling = rolling == "constant_torque" ? RollingModel::ConstantTorque
                 : rolling == "epsd"          ? RollingModel::Spring
                                              : RollingModel::None;
  if (spec.tangential == TangentialModel::LinearHistory && spec.normal == NormalModel::Hertz)
    c.fail("tangential", "\"linear_history\" scales the linear law's k_n, which a Hertz material has not: use \"mindlin\"");
  if (spec.tangential == TangentialModel::Mindlin && spec.normal != NormalModel::Hertz)
    c.fail("tangential", "\"mindlin\" takes its stiffness from the Hertz contact radius: it needs \"normal\": \"hertz\"");
  spec.slip_arm_radius = c.choice_or("slip_lever_arm", {"contact_point", "radius"}, "contact_point") == "radius";
  if (spec.slip_arm_radius && spec.tangential == TangentialModel::None)
    c.fail("slip_lever_arm", "sets the lever arm of the slip velocity: it needs a tangential law");
  spec.rolling_limit_with_dashpot =
      c.choice_or("rolling_limit", {"spring", "spring_and_dashpot"}, "spring") == "spring_and_dashpot";
  if (c.has("rolling_limit") && spec.rolling != RollingModel::Spring)
    c.fail("rolling_limit", "sets the limit of the EPSD rolling spring: it needs \"rolling\": \"epsd\"");
  if (!spec.frictionless_linear() && spec.onset_correction)
    c.fail("onset_correction", "is built for the paper's linear frictionless law only");
  if (spec.normal == NormalModel::Hertz && c.has("cohesion"))
    c.fail("cohesion", "the paper's cohesion zone (10) scales the linear law's k_ij: it is not available with \"normal\": \"hertz\"");
}

/// A pair's own constants instead of the combined ones (docs/case-format.md "material_pairs"):
/// friction (grain–wall usually differs from grain–grain), shear stiffness and tangential damping,
/// and with Hertz the restitution; each key only where a chosen law reads it.
void read_material_pairs(const JsonReader& r, CaseConfig& cfg) {
  const json& list = r.array("material_pairs");
  const ContactSpec& contact = cfg.contact;
  const TangentialModel t = contact.tangential;
  const bool history = t == TangentialModel::LinearHistory || t == TangentialModel::Mindlin;
  const bool hertz = contact.normal == NormalModel::Hertz;
  std::set<std::pair<std::string, std::string>> seen;
  for (std::size_t k = 0; k < list.size(); ++k) {
    const JsonReader e(list[k], r.child_path("material_pairs") + "[" + std::to_string(k) + "]");
    const json& names = e.array("materials");
    if (names.size() != 2 || !names[0].is_string() || !names[1].is_string())
      e.fail("materials", "must name two materials");
    MaterialPairSpec pair;
    pair.a = names[0].get<std::string>();
    pair.b = names[1].get<std::string>();
    for (const std::string& name : {pair.a, pair.b})
      require(cfg.materials.count(name) == 1, e, "materials", "no material named \"" + name + "\"");
    require(seen.insert(std::minmax(pair.a, pair.b)).second, e, "materials", "this pair is given twice");
    refuse_unless(t != TangentialModel::None, e, "friction", "a tangential law (contact.tangential)");
    refuse_unless(contact.rolling != RollingModel::None, e, "rolling_friction", "a rolling law (contact.rolling)");
    refuse_unless(t == TangentialModel::LinearHistory, e, "shear_stiffness_ratio", "contact.tangential \"linear_history\"");
    refuse_unless(history, e, "tangential_damping_ratio", "a history law (\"linear_history\", \"mindlin\")");
    refuse_unless(t == TangentialModel::CoulombSliding, e, "tangential_damping", "contact.tangential \"coulomb_sliding\"");
    // A linear pair's damping is the series of its balls' c_i (11); only Hertz has a ζ per pair.
    refuse_unless(hertz, e, "restitution", "contact.normal \"hertz\" (a linear pair's damping is its balls' c_i in series)");
    refuse_unless(hertz, e, "damping_ratio", "contact.normal \"hertz\" (a linear pair's damping is its balls' c_i in series)");
    const auto optional = [&](const char* key, double hi, const char* unit) -> std::optional<double> {
      if (!e.has(key)) return std::nullopt;
      return e.number_in(key, 0.0, hi, unit);
    };
    pair.friction = optional("friction", limits::kFriction, "");
    pair.rolling_friction = optional("rolling_friction", limits::kFriction, "");
    pair.shear_stiffness_ratio = optional("shear_stiffness_ratio", limits::kFactor, "");
    pair.tangential_damping_ratio = optional("tangential_damping_ratio", limits::kFactor, "");
    pair.tangential_damping = optional("tangential_damping", limits::kDamping, "N s/m");
    if (e.has("restitution") && e.has("damping_ratio")) e.fail("", "give at most one of \"restitution\" or \"damping_ratio\"");
    if (e.has("restitution")) {
      const double res = e.number("restitution");
      require(res > 0.0 && res <= 1.0, e, "restitution", "must be in (0, 1]");
      pair.hertz_damping_ratio = contact::hertz_damping_ratio_for_restitution(res, contact.clamp);
    }
    if (e.has("damping_ratio")) pair.hertz_damping_ratio = e.number_in("damping_ratio", 0.0, limits::kDampingRatio, "");
    e.finish();
    if (!pair.friction && !pair.rolling_friction && !pair.shear_stiffness_ratio && !pair.tangential_damping_ratio &&
        !pair.tangential_damping && !pair.hertz_damping_ratio)
      e.fail("", "give at least one constant for this pair (docs/case-format.md \"Friction\")");
    cfg.contact.material_pairs.push_back(pair);
  }
}

}  // namespace silodem::case_keys
