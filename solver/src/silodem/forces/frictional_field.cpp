#include "silodem/forces/frictional_field.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "silodem/contact/contact_model.hpp"
#include "silodem/contact/pair_constants.hpp"
#include "silodem/forces/contact_history.hpp"
#include "silodem/forces/pair_loop.hpp"

namespace silodem {

namespace {

/// The frictional sub-models (contact/contact_model.hpp) as the pair loop (forces/pair_loop.hpp)
/// calls them: one touching pair in, its force and torques out, its tangential spring kept in
/// the contact history (forces/contact_history.hpp) under the pair's slot. Every evaluation reads
/// the committed spring, so a pair computed twice (by its owner and, with threads, by its
/// neighbour's thread) gives the same bits; only the owner's call stores the trial spring.
template <NormalModel Normal, TangentialModel Tangential, RollingModel Rolling, bool Clamp, bool Cohesion>
class FrictionalLaw {
  static_assert(!Cohesion || Normal == NormalModel::Linear, "the paper's cohesion (9)-(10) scales the linear k_ij");

 public:
  static constexpr bool kTorques = Tangential != TangentialModel::None || Rolling != RollingModel::None;
  static constexpr bool kSpringT = Tangential == TangentialModel::LinearHistory || Tangential == TangentialModel::Mindlin;
  static constexpr bool kSpringR = Rolling == RollingModel::Spring;
  static constexpr bool kHistory = kSpringT || kSpringR;
  // The history's columns: the tangential spring first, then the rolling spring.
  static constexpr int kSprings = int(kSpringT) + int(kSpringR), kColT = 0, kColR = kSprings - 1;
  using History = ContactHistory<(kSprings > 0 ? kSprings : 1)>;

  FrictionalLaw(contact::PairTable table, double dt, double pn_g, double slip_arm_overlap, bool rolling_limit_with_dashpot)
      : table_(std::move(table)), dt_(dt), pn_g_(pn_g), slip_arm_overlap_(slip_arm_overlap),
        rolling_limit_with_dashpot_(rolling_limit_with_dashpot) {}

  bool selected(const Particles& p, std::uint32_t i, std::uint32_t j, double reach) const {
    // With cohesion, a distance bound beyond the law's, as the paper's law takes it (force_field.cpp).
    const double cut = Cohesion ? p.r[i] + p.r[j] + reach * (1.0 + 1e-9) + 1e-15 : p.r[i] + p.r[j];
    return (p.x[i] - p.x[j]).squaredNorm() < cut * cut;
  }

  template <bool Owner>
  [[gnu::always_inline]] PairResult<kTorques> evaluate(const Particles& p, std::size_t s, std::size_t i, std::uint32_t j,
                                                      ForceTotals& t, OverlapMax& om) const {
    const Vec3 d = p.x[i] - p.x[j];
    const double touch = p.r[i] + p.r[j], dist2 = d.squaredNorm();
    if (dist2 >= touch * touch) {  // apart: no contact force (the loop cleared the history)
      if constexpr (Cohesion) return cohesion_zone(p, i, j, d, touch, t);
      return {};
    }
    const double dist = std::sqrt(dist2);
    const bool wall = j >= p.n_mobile;
    contact::ContactState c;
    c.delta = touch - dist;                  // (5)
    c.n = d * (1.0 / dist);                  // (6), from j to i
    c.v_rel = p.v[i] - p.v[j];
    c.delta_rate = -c.v_rel.dot(c.n);
    c.w_i = kTorques ? p.w[i] : Vec3::Zero();
    c.w_j = kTorques ? p.w[j] : Vec3::Zero();
    c.r_i = p.r[i];
    c.r_j = p.r[j];
    c.m_eff = contact::effective_mass(p.m[i], p.m[j], false, wall);
    if constexpr (Rolling == RollingModel::ConstantTorque)  // only its one-step limiter reads it
      c.inertia_eff = wall ? p.inertia(i) : contact::series(p.inertia(i), p.inertia(j));
    if constexpr (kSpringR) {  // about the contact point
      const double about_i = p.inertia(i) + p.m[i] * p.r[i] * p.r[i];
      c.inertia_contact = wall ? about_i : contact::series(about_i, p.inertia(j) + p.m[j] * p.r[j] * p.r[j]);
    }
    c.k_n = contact::series(p.k[i], p.k[j]);  // (11)
    c.c_n = contact::series(p.c[i], p.c[j]);
    c.pair = &table_.at(p.material[i], p.material[j]);
    if constexpr (kSpringT) c.spring = history_.committed(s).col(kColT);
    if constexpr (kSpringR) c.rolling_angle = history_.committed(s).col(kColR);
    c.dt = dt_;
    c.slip_arm_overlap = slip_arm_overlap_;
    c.rolling_limit_with_dashpot = rolling_limit_with_dashpot_;
    const contact::Interaction r = contact::interact<Normal, Tangential, Rolling, Clamp>(c);
    if constexpr (Owner && kSpringT) history_.trial(s).col(kColT) = r.spring;
    if constexpr (Owner && kSpringR) history_.trial(s).col(kColR) = r.rolling_angle;
    t.add(r);
    om.take(c.delta, std::min(c.r_i, c.r_j));
    PairResult<kTorques> out;
    out.f = r.force;
    if constexpr (kTorques) out.torque_i = r.torque_i, out.torque_j = r.torque_j;
    return out;
  }

  /// A pair apart but within the paper's cohesion zone (9)–(10): the tensile spring alone, along
  /// the line of centres. No contact, so no friction, no rolling resistance, no spring kept.
  PairResult<kTorques> cohesion_zone(const Particles& p, std::size_t i, std::uint32_t j, const Vec3& d, double touch,
                                     ForceTotals& t) const {
    const double dist = std::sqrt(d.squaredNorm());
    const Vec3 n = d * (1.0 / dist);
    const double k = contact::series(p.k[i], p.k[j]);  // (11)
    const contact::PairForce pf = contact::cohesion_zone(k, pn_g_, std::min(p.m[i], p.m[j]), touch - dist,
                                                         -(p.v[i] - p.v[j]).dot(n));
    t.elastic_cohesion += pf.elastic;
    t.p_cohesion += pf.p_cohesion;
    t.p_dissipated += pf.p_dissipated;
    PairResult<kTorques> out;
    out.f = pf.f * n;
    return out;
  }

  std::array<HintArray, 8> hint_arrays(const Particles& p) const {
    if constexpr (kTorques)
      return {HintArray::of(p.x), HintArray::of(p.f), HintArray::of(p.v), HintArray::of(p.w),
              HintArray::of(p.r), HintArray::of(p.t), HintArray::of(p.m), HintArray::of(p.x)};
    else
      return {HintArray::of(p.x), HintArray::of(p.f), HintArray::of(p.v), HintArray::of(p.x),
              HintArray::of(p.r), HintArray::of(p.k), HintArray::of(p.c), HintArray::of(p.m)};
  }
  void skip(std::size_t s_begin, std::size_t s_end) const {
    if constexpr (kHistory) history_.clear_trial(s_begin, s_end);
  }
  void prepare(const Particles& p, const NeighbourList& list) const {
    if (kTorques && !p.rotating) throw std::logic_error("frictional force field on balls without rotation");
    if constexpr (kHistory) history_.follow(list, p);
  }
  void commit() {
    if constexpr (kHistory) history_.commit();
  }
  void serialize_history(Archive& a, const NeighbourList& list) {
    if constexpr (kHistory) history_.serialize(a, list);
  }
  std::size_t bytes() const { return history_.bytes(); }

 private:
  contact::PairTable table_;
  double dt_, pn_g_;  // the step; p_N |g| of the cohesion reach (10)
  double slip_arm_overlap_;  // 0.5, or 0 for the radius as lever arm (contact.slip_lever_arm)
  bool rolling_limit_with_dashpot_;  // contact.rolling_limit
  mutable History history_;
};

template <NormalModel N, TangentialModel T, RollingModel R, bool Coh>
std::unique_ptr<ForceField> with_clamp(const CaseConfig& cfg) {
  auto table = contact::pair_table(cfg);
  const double pn_g = cfg.contact.p_n * cfg.gravity.norm();
  const double arm = cfg.contact.slip_arm_radius ? 0.0 : 0.5;
  const bool lim = cfg.contact.rolling_limit_with_dashpot;
  if (cfg.contact.clamp)
    return std::make_unique<PairLoop<FrictionalLaw<N, T, R, true, Coh>>>(FrictionalLaw<N, T, R, true, Coh>(std::move(table), cfg.dt, pn_g, arm, lim));
  return std::make_unique<PairLoop<FrictionalLaw<N, T, R, false, Coh>>>(FrictionalLaw<N, T, R, false, Coh>(std::move(table), cfg.dt, pn_g, arm, lim));
}

template <NormalModel N, TangentialModel T, bool Coh>
std::unique_ptr<ForceField> with_rolling(const CaseConfig& cfg) {
  if (cfg.contact.rolling == RollingModel::ConstantTorque) return with_clamp<N, T, RollingModel::ConstantTorque, Coh>(cfg);
  if (cfg.contact.rolling == RollingModel::Spring) return with_clamp<N, T, RollingModel::Spring, Coh>(cfg);
  return with_clamp<N, T, RollingModel::None, Coh>(cfg);
}

template <NormalModel N, bool Coh>
std::unique_ptr<ForceField> with_tangential(const CaseConfig& cfg) {
  switch (cfg.contact.tangential) {
    case TangentialModel::None: return with_rolling<N, TangentialModel::None, Coh>(cfg);
    case TangentialModel::CoulombSliding: return with_rolling<N, TangentialModel::CoulombSliding, Coh>(cfg);
    case TangentialModel::LinearHistory: return with_rolling<N, TangentialModel::LinearHistory, Coh>(cfg);
    case TangentialModel::Mindlin:
      if constexpr (N == NormalModel::Hertz) return with_rolling<N, TangentialModel::Mindlin, Coh>(cfg);
      break;
  }
  throw std::logic_error("no such tangential law with this normal law");
}

}  // namespace

std::unique_ptr<ForceField> make_frictional_field(const CaseConfig& cfg) {
  if (!(cfg.dt > 0.0)) throw std::invalid_argument("the frictional force field needs the time step");
  if (cfg.contact.onset_correction) throw std::invalid_argument("the onset correction is not available with friction or Hertz contacts");
  if (cfg.contact.normal == NormalModel::Hertz) {
    if (cfg.contact.cohesion) throw std::invalid_argument("the paper's cohesion needs its linear law's k_ij, not Hertz");
    return with_tangential<NormalModel::Hertz, false>(cfg);
  }
  if (cfg.contact.cohesion) return with_tangential<NormalModel::Linear, true>(cfg);
  return with_tangential<NormalModel::Linear, false>(cfg);
}

std::unique_ptr<ForceField> make_force_field(const CaseConfig& cfg) {
  if (cfg.contact.frictionless_linear()) return make_force_field(cfg.contact, cfg.gravity.norm(), cfg.dt);
  return make_frictional_field(cfg);
}

}  // namespace silodem
