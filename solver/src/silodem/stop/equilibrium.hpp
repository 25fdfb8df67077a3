#pragma once
// Local and global out-of-balance stop tests (27)–(29).
#include <vector>

#include "silodem/case/case_config.hpp"
#include "silodem/scene/particles.hpp"

namespace silodem {

struct EquilibriumMeasure {
  double f_max = 0.0;      // (27): max_i |m_i ü_i|
  double f_total = 0.0;    // (28): |Σ_i m_i ü_i| (the printed form drops the squares; docs/model.md §6)
  double eps_f = 0.0;      // p_f × weight of the smallest mobile ball
  double eps_ft = 0.0;     // (29): p_ft |g| Σ m_i
  bool local_ok() const { return f_max < eps_f; }
  bool global_ok() const { return f_total < eps_ft; }
  bool at_rest() const { return local_ok() && global_ok(); }  // Algorithm 5 line 25: both
};

/// docs/model.md §6 Reading: the unbalanced force is the resultant m_i ü_i = f_i + m_i g, not the
/// contact force alone (Algorithm 4 as printed), which never vanishes for a ball resting on others.
EquilibriumMeasure measure_equilibrium(const Particles& p, const std::vector<Vec3>& acceleration, double g_abs,
                                       const EquilibriumSpec& spec);

}  // namespace silodem
