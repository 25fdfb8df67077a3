#include "silodem/contact/pair_table.hpp"

#include <cmath>
#include <stdexcept>

#include "silodem/contact/hertz.hpp"
#include "silodem/contact/pair_constants.hpp"

namespace silodem::contact {

PairParams combine(const Material& a, const Material& b) {
  PairParams p;
  // Geometric means, as LAMMPS `pair granular` mixes its coefficients: a frictionless material
  // makes its pairs frictionless unless "material_pairs" says otherwise.
  p.friction = std::sqrt(a.friction * b.friction);
  p.rolling_friction = std::sqrt(a.rolling_friction * b.rolling_friction);
  // Ratios average, so that equal materials keep theirs exactly.
  p.shear_ratio = 0.5 * (a.shear_stiffness_ratio + b.shear_stiffness_ratio);
  p.shear_damping_ratio = 0.5 * (a.tangential_damping_ratio + b.tangential_damping_ratio);
  p.rolling_damping_ratio = 0.5 * (a.rolling_damping_ratio + b.rolling_damping_ratio);
  p.sliding_damping = series(a.tangential_damping, b.tangential_damping);  // like c_ij (11)
  if (a.youngs_modulus > 0.0 && b.youngs_modulus > 0.0) {
    p.e_star = effective_modulus(a.youngs_modulus, a.poisson_ratio, b.youngs_modulus, b.poisson_ratio);
    p.g_star = effective_shear_modulus(a.youngs_modulus, a.poisson_ratio, b.youngs_modulus, b.poisson_ratio);
    p.hertz_zeta = 0.5 * (a.hertz_damping_ratio + b.hertz_damping_ratio);
  }
  return p;
}

PairTable::PairTable(const std::vector<Material>& materials, const std::vector<MaterialPairSpec>& overrides)
    : n_(materials.size()), table_(n_ * n_) {
  for (const auto& m : materials) names_.push_back(m.name);
  const auto index = [&](const std::string& name) {
    for (std::size_t k = 0; k < n_; ++k)
      if (materials[k].name == name) return k;
    throw std::invalid_argument("material_pairs: no material named " + name);
  };
  for (std::size_t a = 0; a < n_; ++a)
    for (std::size_t b = 0; b < n_; ++b) table_[a * n_ + b] = combine(materials[a], materials[b]);
  for (const auto& o : overrides) {
    const std::size_t a = index(o.a), b = index(o.b);
    for (PairParams* q : {&table_[a * n_ + b], &table_[b * n_ + a]}) {
      if (o.friction) q->friction = *o.friction;
      if (o.rolling_friction) q->rolling_friction = *o.rolling_friction;
      if (o.shear_stiffness_ratio) q->shear_ratio = *o.shear_stiffness_ratio;
      if (o.tangential_damping_ratio) q->shear_damping_ratio = *o.tangential_damping_ratio;
      if (o.tangential_damping) q->sliding_damping = *o.tangential_damping;
      if (o.hertz_damping_ratio) q->hertz_zeta = *o.hertz_damping_ratio;
    }
  }
}

const PairParams& PairTable::at(const std::string& a, const std::string& b) const {
  const auto index = [&](const std::string& name) {
    for (std::size_t k = 0; k < n_; ++k)
      if (names_[k] == name) return std::int32_t(k);
    throw std::invalid_argument("pair table: no material named " + name);
  };
  return at(index(a), index(b));
}

PairTable pair_table(const CaseConfig& cfg) {
  std::vector<Material> materials;
  for (const auto& [name, m] : cfg.materials) materials.push_back(m);  // sorted, as the scene's indices
  return PairTable(materials, cfg.contact.material_pairs);
}

}  // namespace silodem::contact
