#include "silodem/forces/frictional_field.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "silodem/contact/contact_model.hpp"
#include "silodem/contact/pair_constants.hpp"
#include "silodem/core/parallel.hpp"
#include "silodem/forces/contact_history.hpp"

namespace silodem {

namespace {

/// Owner balls per chunk: the unit of the pair pass's energy sums (the same chunks on any thread
/// count, so the same bits).
constexpr std::size_t kChunk = 256;

/// Two passes, both over balls in parallel. The pair pass computes every listed pair once, under
/// its owner, into per-slot results (force on the owner, torques on both balls) and writes the
/// trial history of that slot. The gather pass sums, for each ball, its owned slots in slot order
/// and then the slots where it is the neighbour in slot order: every ball's force and torque is
/// the same sum in the same order for any thread count. Slots hold 72 bytes of results; the
/// frictionless loop of force_field.cpp avoids them, this one keeps the physics plain first.
template <NormalModel Normal, TangentialModel Tangential, RollingModel Rolling, bool Clamp>
class FrictionalField final : public ForceField {
  static constexpr bool kRotates = Tangential != TangentialModel::None || Rolling != RollingModel::None;

 public:
  FrictionalField(contact::PairTable table, double dt) : table_(std::move(table)), dt_(dt) {}

  ForceTotals compute(Particles& p, const NeighbourList& list) const override {
    if (kRotates && !p.rotating) throw std::logic_error("frictional force field on balls without rotation");
    history_.follow(list, p);
    const std::size_t slots = list.pair_count(), nm = p.n_mobile, chunks = (nm + kChunk - 1) / kChunk;
    slot_f_.resize(slots);
    slot_ti_.resize(slots);
    slot_tj_.resize(slots);
    partial_.assign(chunks, ForceTotals{});
    partial_max_.assign(chunks, 0.0);
    const long nc = long(chunks);
    SILODEM_PARALLEL_FOR
    for (long cl = 0; cl < nc; ++cl) pair_pass(p, list, std::size_t(cl));
    const long n = long(p.size());
    SILODEM_PARALLEL_FOR
    for (long jl = 0; jl < n; ++jl) gather(p, list, std::size_t(jl));
    ForceTotals t;
    for (std::size_t c = 0; c < chunks; ++c) {
      const ForceTotals& q = partial_[c];
      t.elastic_contact += q.elastic_contact;
      t.p_dissipated += q.p_dissipated;
      t.elastic_tangential += q.elastic_tangential;
      t.p_friction += q.p_friction;
      t.contacts += q.contacts;
      t.sliding += q.sliding;
      t.max_overlap_ratio = std::max(t.max_overlap_ratio, partial_max_[c]);
    }
    return t;
  }

  void commit() override { history_.commit(); }
  void serialize_history(Archive& a, const NeighbourList& list) override { history_.serialize(a, list); }
  std::size_t bytes() const override {
    return heap_bytes(slot_f_) + heap_bytes(slot_ti_) + heap_bytes(slot_tj_) + heap_bytes(partial_) +
           heap_bytes(partial_max_) + history_.bytes();
  }

 private:
  void pair_pass(const Particles& p, const NeighbourList& list, std::size_t chunk) const {
    ForceTotals t;
    double max_ratio = 0.0;
    const std::size_t s_begin = list.begin(chunk * kChunk), s_end = list.begin(std::min(p.n_mobile, (chunk + 1) * kChunk));
    for (std::size_t s = s_begin; s < s_end; ++s) {
      const std::uint32_t i = list.owner(s), j = list.neighbour(s);
      const Vec3 d = p.x[i] - p.x[j];
      const double touch = p.r[i] + p.r[j], dist2 = d.squaredNorm();
      if (dist2 >= touch * touch) {  // not touching: no force, and the contact's history ends
        slot_f_[s] = slot_ti_[s] = slot_tj_[s] = Vec3::Zero();
        history_.trial(s) = Vec3::Zero();
        continue;
      }
      const double dist = std::sqrt(dist2);
      const bool wall = j >= p.n_mobile;
      contact::ContactState c;
      c.delta = touch - dist;                  // (5)
      c.n = d * (1.0 / dist);                  // (6), from j to i
      c.v_rel = p.v[i] - p.v[j];
      c.delta_rate = -c.v_rel.dot(c.n);
      c.w_i = kRotates ? p.w[i] : Vec3::Zero();
      c.w_j = kRotates ? p.w[j] : Vec3::Zero();
      c.r_i = p.r[i];
      c.r_j = p.r[j];
      c.m_eff = contact::effective_mass(p.m[i], p.m[j], false, wall);
      c.inertia_eff = wall ? p.inertia(i) : contact::series(p.inertia(i), p.inertia(j));
      c.k_n = contact::series(p.k[i], p.k[j]);  // (11)
      c.c_n = contact::series(p.c[i], p.c[j]);
      c.pair = &table_.at(p.material[i], p.material[j]);
      c.spring = history_.committed(s);
      c.dt = dt_;
      const contact::Interaction r = contact::interact<Normal, Tangential, Rolling, Clamp>(c);
      slot_f_[s] = r.force;
      slot_ti_[s] = r.torque_i;
      slot_tj_[s] = r.torque_j;
      history_.trial(s) = r.spring;
      t.elastic_contact += r.elastic_normal;
      t.p_dissipated += r.p_dissipated;
      t.elastic_tangential += r.elastic_tangential;
      t.p_friction += r.p_friction;
      t.sliding += std::size_t(r.sliding);
      ++t.contacts;
      max_ratio = std::max(max_ratio, c.delta / std::min(c.r_i, c.r_j));
    }
    partial_[chunk] = t;
    partial_max_[chunk] = max_ratio;
  }

  void gather(Particles& p, const NeighbourList& list, std::size_t j) const {
    Vec3 f = Vec3::Zero(), torque = Vec3::Zero();
    if (j < p.n_mobile)
      for (std::size_t s = list.begin(j); s < list.end(j); ++s) f += slot_f_[s], torque += slot_ti_[s];
    for (std::size_t k = list.reverse_begin(j); k < list.reverse_end(j); ++k) {
      const std::size_t s = list.reverse_slot(k);
      f -= slot_f_[s];  // (3): the reaction
      torque += slot_tj_[s];
    }
    p.f[j] = f;
    if constexpr (kRotates) p.t[j] = torque;
  }

  contact::PairTable table_;
  double dt_;
  mutable ContactHistory history_;
  mutable std::vector<Vec3> slot_f_, slot_ti_, slot_tj_;  // per slot: force on the owner, torques
  mutable std::vector<ForceTotals> partial_;            // per chunk of owners
  mutable std::vector<double> partial_max_;             // per chunk: largest δ / min(r_i, r_j)
};

template <NormalModel N, TangentialModel T, RollingModel R>
std::unique_ptr<ForceField> with_clamp(const CaseConfig& cfg) {
  auto table = contact::pair_table(cfg);
  if (cfg.contact.clamp) return std::make_unique<FrictionalField<N, T, R, true>>(std::move(table), cfg.dt);
  return std::make_unique<FrictionalField<N, T, R, false>>(std::move(table), cfg.dt);
}

template <NormalModel N, TangentialModel T>
std::unique_ptr<ForceField> with_rolling(const CaseConfig& cfg) {
  if (cfg.contact.rolling == RollingModel::ConstantTorque) return with_clamp<N, T, RollingModel::ConstantTorque>(cfg);
  return with_clamp<N, T, RollingModel::None>(cfg);
}

template <NormalModel N>
std::unique_ptr<ForceField> with_tangential(const CaseConfig& cfg) {
  switch (cfg.contact.tangential) {
    case TangentialModel::None: return with_rolling<N, TangentialModel::None>(cfg);
    case TangentialModel::CoulombSliding: return with_rolling<N, TangentialModel::CoulombSliding>(cfg);
    case TangentialModel::LinearHistory: return with_rolling<N, TangentialModel::LinearHistory>(cfg);
    case TangentialModel::Mindlin: return with_rolling<N, TangentialModel::Mindlin>(cfg);
  }
  throw std::logic_error("unknown tangential model");
}

}  // namespace

std::unique_ptr<ForceField> make_frictional_field(const CaseConfig& cfg) {
  if (!(cfg.dt > 0.0)) throw std::invalid_argument("the frictional force field needs the time step");
  if (cfg.contact.cohesion || cfg.contact.onset_correction)
    throw std::invalid_argument("cohesion and the onset correction are not available with friction or Hertz contacts");
  if (cfg.contact.normal == NormalModel::Hertz) return with_tangential<NormalModel::Hertz>(cfg);
  return with_tangential<NormalModel::Linear>(cfg);
}

std::unique_ptr<ForceField> make_force_field(const CaseConfig& cfg) {
  if (cfg.contact.frictionless_linear()) return make_force_field(cfg.contact, cfg.gravity.norm(), cfg.dt);
  return make_frictional_field(cfg);
}

}  // namespace silodem
