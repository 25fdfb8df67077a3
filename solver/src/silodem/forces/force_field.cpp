#include "silodem/forces/force_field.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "silodem/contact/contact_law.hpp"
#include "silodem/contact/pair_constants.hpp"
#include "silodem/forces/pair_loop.hpp"

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
  // Without a branch on the data: about half the contacts of a dense bed approach, in an order no
  // branch predictor learns (a branch here cost the dense bed +60 % per step). With δ̇ ≤ 0 the
  // quotient is ±inf or negative and the select drops it.
  const double step_approach = delta_rate * dt;
  const double touch_scale = 0.5 + delta / step_approach;
  const bool touched = (delta_rate > 0.0) & (delta < step_approach * (1.0 + 1e-9));
  const double scale = touched ? touch_scale : 1.0;
  if (Clamp || delta_rate >= 0.0) return scale;
  const double a = -0.5 * f * inv_m_eff, b = delta_rate, c = delta;  // a τ² + b τ + c = 0, b < 0 < c
  const double disc = b * b - 4.0 * a * c;
  if (disc < 0.0) return 1.0;  // the tensile force stops the parting first
  const double tau = 2.0 * c / (-b + std::sqrt(disc));  // the smaller positive root, stable form
  return tau < dt ? 0.5 + tau / dt : 1.0;
}

/// The paper's law as the pair loop (forces/pair_loop.hpp) calls it: linear spring–dashpot (4),
/// series constants (11), cohesion (9)–(10), the onset correction above. No torques, no history.
template <bool Cohesion, bool Clamp, bool Onset>
class KelvinVoigtLaw {
 public:
  static constexpr bool kTorques = false;
  KelvinVoigtLaw(double p_n, double g_abs, double dt) : pn_g_(p_n * g_abs), dt_(dt) {}

  /// Without cohesion the test is evaluate's own; with it, a distance bound beyond the law's. Either
  /// way a pair left out is one the law would have given zero.
  bool selected(const Particles& p, std::uint32_t i, std::uint32_t j, double reach) const {
    if constexpr (Cohesion) {
      // The cohesion zone reaches |δ_c| ≤ reach beyond touching (10): a pair farther apart gets no
      // force. The margin keeps a pair exactly at the reach, which the law still pulls (δ = δ_c),
      // whatever the rounding of the distance.
      const double cut = p.r[i] + p.r[j] + reach * (1.0 + 1e-9) + 1e-15;
      return (p.x[i] - p.x[j]).squaredNorm() < cut * cut;
    } else {
      const double touch = p.r[i] + p.r[j];
      return (p.x[i] - p.x[j]).squaredNorm() < touch * touch;
    }
  }

  /// The force of the pair (i, j) on i, zero if they do not interact; adds its energy terms to t.
  /// Always inlined: called from inside the threads' lambdas, GCC had kept it out of line (perf).
  template <bool Owner>
  [[gnu::always_inline]] PairResult<false> evaluate(const Particles& p, std::size_t, std::size_t i, std::uint32_t j,
                                                   ForceTotals& t, OverlapMax& om) const {
    const Vec3 d = p.x[i] - p.x[j];
    const double dist2 = d.squaredNorm();
    const double ri = p.r[i], rj = p.r[j];
    const double touch = ri + rj;
    if (!Cohesion && dist2 >= touch * touch) return {};
    const double dist = std::sqrt(dist2);
    const double delta = touch - dist;                 // (5)
    const double k = contact::series(p.k[i], p.k[j]);  // (11)
    contact::PairForce pf;
    const Vec3 n = d * (1.0 / dist);                      // (6), from j to i
    const double delta_rate = -(p.v[i] - p.v[j]).dot(n);  // dδ/dt, > 0 approaching (docs/model.md §2.2 Reading of (7))
    if (delta > 0.0) {
      double c = contact::series(p.c[i], p.c[j]);
      if constexpr (Onset)
        c *= onset_scale<Clamp>(delta, delta_rate, dt_, k * delta + c * delta_rate,
                                1.0 / p.m[i] + (j < p.n_mobile ? 1.0 / p.m[j] : 0.0));
      pf = contact::kelvin_voigt<Clamp>(k, c, delta, delta_rate);  // (4)
      t.elastic_contact += pf.elastic;
      om.take(delta, std::min(ri, rj));
      ++t.contacts;
    } else if constexpr (Cohesion) {
      pf = contact::cohesion_zone(k, pn_g_, std::min(p.m[i], p.m[j]), delta, delta_rate);  // (9)–(10)
      t.elastic_cohesion += pf.elastic;
      t.p_cohesion += pf.p_cohesion;
    }
    t.p_dissipated += pf.p_dissipated;
    return {pf.f * n};
  }

  std::array<HintArray, 8> hint_arrays(const Particles& p) const {
    // x twice: the selection pass reads it first. At about 4.6 slots per ball a 24-byte array is
    // asked for every 1.7 balls, and its lines hold 2.7.
    return {HintArray::of(p.x), HintArray::of(p.f), HintArray::of(p.v), HintArray::of(p.x),
            HintArray::of(p.r), HintArray::of(p.k), HintArray::of(p.c), Cohesion || Onset ? HintArray::of(p.m) : HintArray::of(p.f)};
  }
  void skip(std::size_t, std::size_t) const {}
  void prepare(const Particles&, const NeighbourList&) const {}
  void commit() {}
  void serialize_history(Archive&, const NeighbourList&) {}
  std::size_t bytes() const { return 0; }

 private:
  double pn_g_, dt_;
};

template <bool Cohesion, bool Clamp>
std::unique_ptr<ForceField> with_onset(const ContactSpec& spec, double g_abs, double dt) {
  if (spec.onset_correction) return std::make_unique<PairLoop<KelvinVoigtLaw<Cohesion, Clamp, true>>>(KelvinVoigtLaw<Cohesion, Clamp, true>(spec.p_n, g_abs, dt));
  return std::make_unique<PairLoop<KelvinVoigtLaw<Cohesion, Clamp, false>>>(KelvinVoigtLaw<Cohesion, Clamp, false>(spec.p_n, g_abs, dt));
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
