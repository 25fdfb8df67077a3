#pragma once
// The constants of every material pair that the contact sub-models need beyond the per-ball k_i,
// c_i of the paper: friction, rolling friction, shear stiffness, Hertz moduli. Combined from the
// two materials by the rules of docs/model.md §10.4 unless the case gives the pair itself
// ("material_pairs"). Built once per scene; the force loop reads it by the balls' material indices.
#include <cstdint>
#include <string>
#include <vector>

#include "silodem/case/case_config.hpp"

namespace silodem::contact {

struct PairParams {
  double friction = 0.0;           // μ_ij
  double rolling_friction = 0.0;   // μ_r,ij
  double rolling_damping_ratio = 0.0;  // η_r,ij of the EPSD rolling dashpot
  double shear_ratio = 0.0;        // k_t / k_n of the linear history spring
  double shear_damping_ratio = 0.0;// γ_t / c_n of the linear history spring
  double sliding_damping = 0.0;    // γ_t of the sliding law, N s/m (series of the materials')
  double e_star = 0.0, g_star = 0.0, hertz_zeta = 0.0;  // Hertz–Mindlin
};

class PairTable {
 public:
  PairTable() = default;
  /// Materials in the scene's index order (scene/scene_builder.hpp: the case's names, sorted).
  PairTable(const std::vector<Material>& materials, const std::vector<MaterialPairSpec>& overrides);
  const PairParams& at(std::int32_t a, std::int32_t b) const { return table_[std::size_t(a) * n_ + std::size_t(b)]; }
  /// By the materials' names (set-up and checks; the force loop uses the indices).
  const PairParams& at(const std::string& a, const std::string& b) const;
  std::size_t materials() const { return n_; }

 private:
  std::size_t n_ = 0;
  std::vector<std::string> names_;
  std::vector<PairParams> table_;
};

/// The combination rules alone (docs/model.md §10.4), for one pair of materials.
PairParams combine(const Material& a, const Material& b);

/// The table of a case's materials, in the scene's index order.
PairTable pair_table(const CaseConfig& cfg);

}  // namespace silodem::contact
