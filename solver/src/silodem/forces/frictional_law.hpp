#pragma once
// The contact law of scenes with friction, rotation, rolling resistance, Hertz contacts or breakage
// (docs/model.md §10, §14): the sub-models are template parameters chosen once per scene
// (forces/frictional_field.cpp), so the pair loop (forces/pair_loop.hpp) holds no per-contact dispatch.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include "silodem/contact/contact_model.hpp"
#include "silodem/contact/pair_constants.hpp"
#include "silodem/contact/pair_table.hpp"
#include "silodem/forces/contact_history.hpp"
#include "silodem/forces/pair_loop.hpp"

namespace silodem {

/// The frictional sub-models (contact/contact_model.hpp) as the pair loop (forces/pair_loop.hpp)
/// calls them: one touching pair in, its force and torques out, its tangential spring kept in
/// the contact history (forces/contact_history.hpp) under the pair's slot. Every evaluation reads
/// the committed spring, so a pair computed twice (by its owner and, with threads, by its
/// neighbour's thread) gives the same bits; only the owner's call stores the trial spring.
/// With `Breakage` (docs/model.md §14) each contact also keeps, in a last history column,
/// (E_max, exempt, 1): the largest elastic energy of its normal law so far, whether it was born
/// overlapping a fragment (then it carries no force until it ends, notes B11), and a mark that it
/// exists; a contact whose mark the accepted step cleared has ended (take_ended). Entries are read
/// as magnitudes: the history flips a column's sign when a pair's order does.
template <NormalModel Normal, TangentialModel Tangential, RollingModel Rolling, bool Clamp, bool Cohesion,
          bool Breakage = false>
class FrictionalLaw {
  static_assert(!Cohesion || Normal == NormalModel::Linear, "the paper's cohesion (9)-(10) scales the linear k_ij");

 public:
  static constexpr bool kTorques = Tangential != TangentialModel::None || Rolling != RollingModel::None;
  static constexpr bool kSpringT = Tangential == TangentialModel::LinearHistory || Tangential == TangentialModel::Mindlin;
  static constexpr bool kSpringR = Rolling == RollingModel::Spring;
  static constexpr bool kHistory = kSpringT || kSpringR || Breakage;
  // The history's columns: the tangential spring first, then the rolling spring, then breakage's.
  static constexpr int kSprings = int(kSpringT) + int(kSpringR) + int(Breakage), kColT = 0,
                       kColR = int(kSpringT), kColB = kSprings - 1;
  using History = ContactHistory<(kSprings > 0 ? kSprings : 1)>;

  /// `secant_energy`: breakage books ½ F δ (1.25 × the Hertz energy, the thesis code's) for a contact's energy.
  FrictionalLaw(contact::PairTable table, double dt, double pn_g, double slip_arm_overlap, bool rolling_limit_with_dashpot,
                bool secant_energy = false)
      : table_(std::move(table)), dt_(dt), pn_g_(pn_g), slip_arm_overlap_(slip_arm_overlap),
        rolling_limit_with_dashpot_(rolling_limit_with_dashpot),
        energy_factor_(secant_energy && Normal == NormalModel::Hertz ? 1.25 : 1.0) {}

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
    if constexpr (Breakage)
      if (exempt(s, i, j)) {
        if constexpr (Owner) history_.trial(s).col(kColB) = Vec3(0.0, 1.0, 1.0);
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
    if constexpr (Owner && Breakage) {
      const double e_max = std::max(std::abs(history_.committed(s)(0, kColB)), energy_factor_ * r.elastic_normal);
      history_.trial(s).col(kColB) = Vec3(e_max, 0.0, 1.0);
    }
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
    if constexpr (Breakage) mark_newborn(p);
  }
  void commit() {
    if constexpr (Breakage) {
      history_.for_each_ended(kColB, [&](std::int64_t a, std::int64_t b, const auto& state) {
        if (state(1, kColB) == 0.0) ended_.push_back({a, b, std::abs(state(0, kColB))});
      });
      newborn_tags_.clear();
    }
    if constexpr (kHistory) history_.commit();
  }
  std::vector<ContactEnd> take_ended() { return std::exchange(ended_, {}); }
  void set_newborn(std::vector<std::int64_t> tags) {
    std::sort(tags.begin(), tags.end());
    newborn_tags_ = std::move(tags);
  }
  void serialize_history(Archive& a, const NeighbourList& list) {
    if constexpr (kHistory) history_.serialize(a, list);
  }
  std::size_t bytes() const { return history_.bytes(); }
  std::vector<char> export_history(std::size_t begin, std::size_t end) const {
    if constexpr (kHistory) return history_.export_owned(begin, end);
    return {};
  }
  void adopt_history(const std::vector<char>& records) {
    if constexpr (kHistory) history_.adopt(records);
  }

 private:
  /// A contact met for the first time is exempt if one of its balls was born in this step's break.
  bool exempt(std::size_t s, std::size_t i, std::uint32_t j) const {
    const auto& prev = history_.committed(s);
    if (prev(2, kColB) != 0.0) return prev(1, kColB) != 0.0;
    return !newborn_.empty() && (newborn_[i] | newborn_[j]);
  }
  void mark_newborn(const Particles& p) const {
    newborn_.clear();
    if (newborn_tags_.empty()) return;
    newborn_.assign(p.size(), 0);
    for (std::size_t i = 0; i < p.size(); ++i)
      newborn_[i] = std::uint8_t(std::binary_search(newborn_tags_.begin(), newborn_tags_.end(), p.tag[i]));
  }

  contact::PairTable table_;
  double dt_, pn_g_;  // the step; p_N |g| of the cohesion reach (10)
  double slip_arm_overlap_;  // 0.5, or 0 for the radius as lever arm (contact.slip_lever_arm)
  bool rolling_limit_with_dashpot_;  // contact.rolling_limit
  double energy_factor_;              // breakage: the contact energy per unit of the normal law's elastic energy
  mutable History history_;
  std::vector<ContactEnd> ended_;          // breakage: contacts ended in the steps since take_ended
  std::vector<std::int64_t> newborn_tags_;  // breakage: fragments born since the last commit
  mutable std::vector<std::uint8_t> newborn_;  // per ball, from newborn_tags_ at each evaluation
};

}  // namespace silodem
