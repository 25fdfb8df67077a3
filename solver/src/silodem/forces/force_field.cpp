#include "silodem/forces/force_field.hpp"

#include <algorithm>
#include <cmath>

#include "silodem/contact/contact_law.hpp"
#include "silodem/contact/pair_constants.hpp"

namespace silodem {

namespace {

template <bool Cohesion, bool Clamp>
class KelvinVoigtField final : public ForceField {
 public:
  KelvinVoigtField(double p_n, double g_abs) : pn_g_(p_n * g_abs) {}

  ForceTotals compute(Particles& p, const NeighbourList& list) const override {
    ForceTotals t;
    for (auto& f : p.f) f.setZero();
    for (std::size_t i = 0; i < p.n_mobile; ++i) {
      const Vec3 xi = p.x[i], vi = p.v[i];
      const double ri = p.r[i], ki = p.k[i], ci = p.c[i];
      Vec3 fi = Vec3::Zero();
      for (std::size_t s = list.begin(i); s < list.end(i); ++s) {
        const std::uint32_t j = list.neighbour(s);
        const Vec3 d = xi - p.x[j];
        const double dist2 = d.squaredNorm();
        const double touch = ri + p.r[j];
        if (!Cohesion && dist2 >= touch * touch) continue;
        const double dist = std::sqrt(dist2);
        const double delta = touch - dist;                 // (5)
        const double k = contact::series(ki, p.k[j]);      // (11)
        contact::PairForce pf;
        const Vec3 n = d / dist;                            // (6), from j to i
        const double delta_rate = -(vi - p.v[j]).dot(n);    // dδ/dt, > 0 approaching (MODEL §2 Reading of (7))
        if (delta > 0.0) {
          pf = contact::kelvin_voigt<Clamp>(k, contact::series(ci, p.c[j]), delta, delta_rate);  // (4)
          t.elastic_contact += pf.elastic;
          t.max_overlap_ratio = std::max(t.max_overlap_ratio, delta / std::min(ri, p.r[j]));
          ++t.contacts;
        } else if constexpr (Cohesion) {
          const double delta_c = contact::cohesion_reach(1.0, pn_g_, std::min(p.m[i], p.m[j]), k);  // (10)
          if (delta < delta_c) continue;
          pf = contact::cohesion(k, delta_c, delta, delta_rate);  // (9)
          t.elastic_cohesion += pf.elastic;
          t.p_cohesion += pf.p_cohesion;
        }
        t.p_dissipated += pf.p_dissipated;
        const Vec3 fij = pf.f * n;                          // (3): equal and opposite on j
        fi += fij;
        p.f[j] -= fij;
      }
      p.f[i] += fi;
    }
    return t;
  }

 private:
  double pn_g_;
};

}  // namespace

std::unique_ptr<ForceField> make_force_field(const ContactSpec& spec, double g_abs) {
  if (spec.cohesion) {
    if (spec.clamp) return std::make_unique<KelvinVoigtField<true, true>>(spec.p_n, g_abs);
    return std::make_unique<KelvinVoigtField<true, false>>(spec.p_n, g_abs);
  }
  if (spec.clamp) return std::make_unique<KelvinVoigtField<false, true>>(spec.p_n, g_abs);
  return std::make_unique<KelvinVoigtField<false, false>>(spec.p_n, g_abs);
}

double max_cohesion_reach(const Particles& p, const ContactSpec& spec, double g_abs, double extra_mass_max,
                          double extra_k_min) {
  if (!spec.cohesion) return 0.0;
  // |δ_c| = p_N g min(m)/k_ij grows with mass and falls with stiffness: bound it with the largest
  // mass and the smallest per-ball stiffness present (k_ij ≥ k_min/2).
  double m_max = extra_mass_max, k_min = extra_k_min > 0.0 ? extra_k_min : 1e300;
  for (std::size_t i = 0; i < p.size(); ++i) {
    m_max = std::max(m_max, p.m[i]);
    k_min = std::min(k_min, p.k[i]);
  }
  return spec.p_n * g_abs * m_max / (0.5 * k_min);
}

}  // namespace silodem
