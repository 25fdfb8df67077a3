#pragma once
// Local and global out-of-balance stop tests (27)–(29), and the kinetic test that by default must
// hold with them (docs/case-format.md, `equilibrium`).
//
// Why a kinetic test: (27)–(29) bound forces, and a column passes them while it still swings
// through its static state. On a stack of n balls the overlap errors e_j obey only
// |e_i − e_{i−1}| < p_f m g/k (27) and |e_n| < p_ft n m g/k (28)–(29), so under the top ball the
// error may reach (p_ft n + (n − 1) p_f) m g/k: the whole static overlap m g/k for n = 10.
// A ten-ball column started touching passes (27)–(29) after 1.6 ms with E_kin ≈ E_el. Requiring
// E_kin < p_k E_el as well stops it only once the swing has died down: the energy of the
// motion left is that fraction of the energy stored in the contacts.
#include <vector>

#include "silodem/case/case_config.hpp"
#include "silodem/scene/particles.hpp"

namespace silodem {

struct EquilibriumMeasure {
  double f_max = 0.0;      // (27): max_i |m_i ü_i|
  double f_total = 0.0;    // (28): |Σ_i m_i ü_i| (the printed form drops the squares; docs/model.md §6)
  double eps_f = 0.0;      // p_f × weight of the smallest mobile ball
  double eps_ft = 0.0;     // (29): p_ft |g| Σ m_i
  double e_kin = 0.0;      // kinetic energy of the mobile balls, J
  double e_el = 0.0;       // elastic energy in the contacts (walls included), J
  double eps_k = 0.0;      // p_k × e_el
  bool kinetic = true;     // whether the kinetic test counts (false: the paper-literal test)
  bool local_ok() const { return f_max < eps_f; }
  bool global_ok() const { return f_total < eps_ft; }
  bool kinetic_ok() const { return !kinetic || e_kin < eps_k; }
  bool at_rest() const { return local_ok() && global_ok() && kinetic_ok(); }  // Algorithm 5 line 25: all
};

/// docs/model.md §6 Reading: the unbalanced force is the resultant m_i ü_i = f_i + m_i g, not the
/// contact force alone (Algorithm 4 as printed), which never vanishes for a ball resting on others.
/// `kinetic` and `elastic` are the energy ledger's terms at the same state.
EquilibriumMeasure measure_equilibrium(const Particles& p, const std::vector<Vec3>& acceleration, double g_abs,
                                       const EquilibriumSpec& spec, double kinetic, double elastic);

}  // namespace silodem
