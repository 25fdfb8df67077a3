#include "silodem/forces/force_field.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "silodem/contact/contact_law.hpp"
#include "silodem/contact/pair_constants.hpp"
#include "silodem/core/parallel.hpp"

namespace silodem {

namespace {

/// Dashpot scale in the step next to first touch (δ̇ > 0) or, unclamped, to separation (δ̇ < 0):
/// the contact fills only a fraction θ of the interval next to this step, but the trapezoid
/// impulse of every scheme here — ½Δt (F_n−1 + F_n) — books the jump of the dashpot force c δ̇ over
/// half an interval. Scaling the dashpot by θ + ½ in that one step gives the interval the impulse
/// c δ̇ θ Δt: the O(ζ ω Δt) error in e becomes O((ω Δt)²). Both balls get the same scaled force, so
/// momentum is conserved. Touch: θ = δ/(δ̇ Δt) < 1, the overlap one step's approach makes (a
/// quadratic in the deceleration was tried: 10× larger errors at ζ = 0.9, t_c/50). Separation:
/// θΔt is the root of δ + δ̇ τ + ½ δ̈ τ² = 0 with δ̈ = −f/m_eff, since the unclamped tensile dashpot
/// slows the parting and the linear guess would fire in several steps. A clamped law's force goes
/// to zero continuously before separation (a kink, not a jump): left alone there.
template <bool Clamp>
inline double onset_scale(double delta, double delta_rate, double dt, double f, double inv_m_eff) {
  // θ = 1 up to rounding is a touch exactly on the previous step (δ was 0 there, no force yet).
  if (delta_rate > 0.0) return delta < delta_rate * dt * (1.0 + 1e-9) ? 0.5 + delta / (delta_rate * dt) : 1.0;
  if (Clamp || delta_rate == 0.0) return 1.0;
  const double a = -0.5 * f * inv_m_eff, b = delta_rate, c = delta;  // a τ² + b τ + c = 0, b < 0 < c
  const double disc = b * b - 4.0 * a * c;
  if (disc < 0.0) return 1.0;  // the tensile force stops the parting first
  const double tau = 2.0 * c / (-b + std::sqrt(disc));  // the smaller positive root, stable form
  return tau < dt ? 0.5 + tau / dt : 1.0;
}

template <bool Cohesion, bool Clamp, bool Onset>
class KelvinVoigtField final : public ForceField {
 public:
  KelvinVoigtField(double p_n, double g_abs, double dt) : pn_g_(p_n * g_abs), dt_(dt) {}

  // Two passes, so that any number of threads gives the same bits (core/parallel.hpp): each
  // mobile ball i sums the pairs it owns into f_i and stores each pair force; then every ball
  // subtracts the reactions of the pairs that list it as the neighbour, in slot order.
  ForceTotals compute(Particles& p, const NeighbourList& list) const override {
    const std::size_t n = p.size(), nm = p.n_mobile;
    pair_f_.resize(list.pair_count());
    partial_.resize(nm);
    const long nml = long(nm);
    SILODEM_PARALLEL_FOR
    for (long il = 0; il < nml; ++il) {
      const std::size_t i = std::size_t(il);
      const Vec3 xi = p.x[i], vi = p.v[i];
      const double ri = p.r[i], ki = p.k[i], ci = p.c[i];
      Vec3 fi = Vec3::Zero();
      ForceTotals t;
      for (std::size_t s = list.begin(i); s < list.end(i); ++s) {
        const std::uint32_t j = list.neighbour(s);
        const Vec3 fij = pair_force(p, i, j, xi, vi, ri, ki, ci, t);  // (3): equal and opposite on j
        pair_f_[s] = fij;
        fi += fij;
      }
      p.f[i] = fi;
      partial_[i] = t;
    }
    const long nl = long(n);
    SILODEM_PARALLEL_FOR
    for (long jl = 0; jl < nl; ++jl) {
      const std::size_t j = std::size_t(jl);
      Vec3 f = j < nm ? p.f[j] : Vec3::Zero();
      for (std::size_t k = list.reverse_begin(j); k < list.reverse_end(j); ++k) f -= pair_f_[list.reverse_slot(k)];
      p.f[j] = f;
    }
    ForceTotals t;
    for (const ForceTotals& q : partial_) {
      t.elastic_contact += q.elastic_contact;
      t.elastic_cohesion += q.elastic_cohesion;
      t.p_dissipated += q.p_dissipated;
      t.p_cohesion += q.p_cohesion;
      t.max_overlap_ratio = std::max(t.max_overlap_ratio, q.max_overlap_ratio);
      t.contacts += q.contacts;
    }
    return t;
  }

  std::size_t bytes() const override { return heap_bytes(pair_f_) + heap_bytes(partial_); }

 private:
  /// The force of the pair (i, j) on i, zero if they do not interact; adds its energy terms to t.
  Vec3 pair_force(const Particles& p, std::size_t i, std::uint32_t j, const Vec3& xi, const Vec3& vi, double ri,
                  double ki, double ci, ForceTotals& t) const {
    const Vec3 d = xi - p.x[j];
    const double dist2 = d.squaredNorm();
    const double touch = ri + p.r[j];
    if (!Cohesion && dist2 >= touch * touch) return Vec3::Zero();
    const double dist = std::sqrt(dist2);
    const double delta = touch - dist;                 // (5)
    const double k = contact::series(ki, p.k[j]);      // (11)
    contact::PairForce pf;
    const Vec3 n = d / dist;                            // (6), from j to i
    const double delta_rate = -(vi - p.v[j]).dot(n);    // dδ/dt, > 0 approaching (MODEL §2 Reading of (7))
    if (delta > 0.0) {
      double c = contact::series(ci, p.c[j]);
      if constexpr (Onset)
        c *= onset_scale<Clamp>(delta, delta_rate, dt_, k * delta + c * delta_rate,
                                1.0 / p.m[i] + (j < p.n_mobile ? 1.0 / p.m[j] : 0.0));
      pf = contact::kelvin_voigt<Clamp>(k, c, delta, delta_rate);  // (4)
      t.elastic_contact += pf.elastic;
      t.max_overlap_ratio = std::max(t.max_overlap_ratio, delta / std::min(ri, p.r[j]));
      ++t.contacts;
    } else if constexpr (Cohesion) {
      const double delta_c = contact::cohesion_reach(1.0, pn_g_, std::min(p.m[i], p.m[j]), k);  // (10)
      if (delta < delta_c) return Vec3::Zero();
      pf = contact::cohesion(k, delta_c, delta, delta_rate);  // (9)
      t.elastic_cohesion += pf.elastic;
      t.p_cohesion += pf.p_cohesion;
    }
    t.p_dissipated += pf.p_dissipated;
    return pf.f * n;
  }

  mutable std::vector<Vec3> pair_f_;        // per list slot: the force on its owner i
  mutable std::vector<ForceTotals> partial_; // per mobile ball: the terms of the pairs it owns
  double pn_g_, dt_;
};

template <bool Cohesion, bool Clamp>
std::unique_ptr<ForceField> with_onset(const ContactSpec& spec, double g_abs, double dt) {
  if (spec.onset_correction) return std::make_unique<KelvinVoigtField<Cohesion, Clamp, true>>(spec.p_n, g_abs, dt);
  return std::make_unique<KelvinVoigtField<Cohesion, Clamp, false>>(spec.p_n, g_abs, dt);
}

}  // namespace

std::unique_ptr<ForceField> make_force_field(const ContactSpec& spec, double g_abs, double dt) {
  if (spec.onset_correction && !(dt > 0.0)) throw std::invalid_argument("onset correction needs the time step");
  if (spec.cohesion) return spec.clamp ? with_onset<true, true>(spec, g_abs, dt) : with_onset<true, false>(spec, g_abs, dt);
  return spec.clamp ? with_onset<false, true>(spec, g_abs, dt) : with_onset<false, false>(spec, g_abs, dt);
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
