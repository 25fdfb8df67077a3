#include "silodem/stop/equilibrium.hpp"

#include <algorithm>

namespace silodem {

EquilibriumMeasure measure_equilibrium(const Particles& p, const std::vector<Vec3>& acceleration, double g_abs,
                                       const EquilibriumSpec& spec, double kinetic, double elastic) {
  EquilibriumMeasure m;
  Vec3 sum = Vec3::Zero();
  double mass = 0.0, m_min = 1e300;
  for (std::size_t i = 0; i < p.n_mobile; ++i) {
    const Vec3 unbalanced = p.m[i] * acceleration[i];
    m.f_max = std::max(m.f_max, unbalanced.norm());
    sum += unbalanced;
    mass += p.m[i];
    m_min = std::min(m_min, p.m[i]);
  }
  m.f_total = sum.norm();
  m.eps_f = p.n_mobile ? spec.p_f * g_abs * m_min : 0.0;
  m.eps_ft = spec.p_ft * g_abs * mass;
  m.e_kin = kinetic;
  m.e_el = elastic;
  m.kinetic = spec.test == EquilibriumTest::ForcesAndKinetic;
  m.eps_k = spec.p_k * elastic;
  return m;
}

}  // namespace silodem
