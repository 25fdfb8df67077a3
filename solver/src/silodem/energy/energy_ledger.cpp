#include "silodem/energy/energy_ledger.hpp"

#include "silodem/checkpoint/archive.hpp"
#include "silodem/core/parallel.hpp"
#include "silodem/core/partition.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace silodem {

void EnergyLedger::totals(const Particles& p, const ForceTotals& t) {
  // Per chunk, then over chunks in order: the same bits for any thread count (core/parallel.hpp),
  // and for any number of processes, whose shares start at chunk edges (core/partition.hpp).
  const Partition* part = partition();
  const std::size_t first = part ? part->own_begin : 0, last = part ? part->own_end : p.n_mobile;
  const std::size_t chunks = sum_chunks(last - first);
  chunk_sums_.resize(3 * chunks);
  const long nc = long(chunks);
  SILODEM_PARALLEL_FOR
  for (long cl = 0; cl < nc; ++cl) {
    double kin = 0.0, grav = 0.0, rot = 0.0;
    const std::size_t begin = first + std::size_t(cl) * kSumChunk, end = std::min(last, begin + kSumChunk);
    for (std::size_t i = begin; i < end; ++i) {
      kin += 0.5 * p.m[i] * p.v[i].squaredNorm();
      grav -= p.m[i] * g_.dot(p.x[i]);
    }
    if (p.rotating)
      for (std::size_t i = begin; i < end; ++i) rot += 0.5 * p.inertia(i) * p.w[i].squaredNorm();
    chunk_sums_[3 * std::size_t(cl)] = kin;
    chunk_sums_[3 * std::size_t(cl) + 1] = grav;
    chunk_sums_[3 * std::size_t(cl) + 2] = rot;
  }
  if (part) chunk_sums_ = part->gather_values(chunk_sums_);
  s_.kinetic = 0.0;
  s_.gravitational = 0.0;
  s_.rotational = 0.0;
  for (std::size_t c = 0; c < chunk_sums_.size() / 3; ++c) {
    s_.kinetic += chunk_sums_[3 * c];
    s_.gravitational += chunk_sums_[3 * c + 1];
    s_.rotational += chunk_sums_[3 * c + 2];
  }
  s_.kinetic += s_.rotational;
  s_.elastic_tangential = t.elastic_tangential;
  s_.elastic_rolling = t.elastic_rolling;
  s_.elastic = t.elastic_contact + t.elastic_cohesion + t.elastic_tangential + t.elastic_rolling;
  // The friction laws' work, less what their springs still hold, has been dissipated.
  s_.friction_dissipated = friction_work_ - t.elastic_tangential - t.elastic_rolling;
  // Energy that flowed into cohesion springs, minus what they hold now, is what springs carried
  // away when they let go (zone exit, or the pair turning to approach): no per-pair history needed.
  s_.cohesion_removed = cohesion_inflow_ - t.elastic_cohesion;
  mechanical_max_ = std::max(mechanical_max_, s_.kinetic + s_.elastic);
  s_.scale = mechanical_max_ + s_.dissipated + cohesion_inflow_ + friction_work_;
  s_.balance = s_.kinetic + s_.gravitational + s_.elastic + s_.dissipated + s_.cohesion_removed +
               s_.friction_dissipated - s_.initial - s_.injected + s_.withdrawn;
  max_drift_ = std::max(max_drift_, std::abs(s_.relative_drift()));
}

void EnergyLedger::start(const Particles& p, const ForceTotals& t, double time) {
  s_ = EnergyState{};
  s_.t = time;
  cohesion_inflow_ = t.elastic_cohesion;
  p_diss_prev_ = t.p_dissipated;
  p_coh_prev_ = t.p_cohesion;
  p_friction_prev_ = t.p_friction;
  friction_work_ = t.elastic_tangential + t.elastic_rolling;  // springs loaded at t = 0 hold energy not yet lost
  mechanical_max_ = 0.0;
  totals(p, t);
  s_.initial = s_.kinetic + s_.gravitational + s_.elastic;
  s_.balance = 0.0;
  max_drift_ = 0.0;
}

void EnergyLedger::record(const Particles& p, const ForceTotals& t, double time, double dt) {
  s_.t = time;
  s_.dissipated += 0.5 * dt * (p_diss_prev_ + t.p_dissipated);
  cohesion_inflow_ += 0.5 * dt * (p_coh_prev_ + t.p_cohesion);
  friction_work_ += 0.5 * dt * (p_friction_prev_ + t.p_friction);
  p_diss_prev_ = t.p_dissipated;
  p_coh_prev_ = t.p_cohesion;
  p_friction_prev_ = t.p_friction;
  totals(p, t);
}

double EnergyLedger::book_breakage(const Particles& p, const ForceTotals& t) {
  const double before = s_.balance, drift_max = max_drift_;
  p_diss_prev_ = t.p_dissipated;
  p_coh_prev_ = t.p_cohesion;
  p_friction_prev_ = t.p_friction;
  totals(p, t);
  const double jump = s_.balance - before;
  s_.injected += jump;
  s_.balance -= jump;
  max_drift_ = std::max(drift_max, std::abs(s_.relative_drift()));
  return jump;
}

void EnergyLedger::inject(double m, const Vec3& x, const Vec3& v) {
  s_.injected += 0.5 * m * v.squaredNorm() - m * g_.dot(x);
}

nlohmann::json EnergyLedger::summary() const {
  nlohmann::json j = {{"kinetic", s_.kinetic},
          {"gravitational", s_.gravitational},
          {"elastic", s_.elastic},
          {"dissipated", s_.dissipated},
          {"cohesion_removed", s_.cohesion_removed},
          {"injected", s_.injected},
          {"withdrawn", s_.withdrawn},
          {"initial", s_.initial},
          {"balance", s_.balance},
          {"scale", s_.scale},
          {"relative_drift", s_.relative_drift()},
          {"max_abs_relative_drift", max_drift_}};
  if (with_friction_) {
    j["rotational"] = s_.rotational;
    j["elastic_tangential"] = s_.elastic_tangential;
    j["elastic_rolling"] = s_.elastic_rolling;
    j["friction_dissipated"] = s_.friction_dissipated;
  }
  return j;
}

void EnergyLedger::withdraw(double m, const Vec3& x, const Vec3& v) {
  s_.withdrawn += 0.5 * m * v.squaredNorm() - m * g_.dot(x);
}

void EnergyLedger::withdraw_ball(const Particles& p, std::size_t i) {
  withdraw(p.m[i], p.x[i], p.v[i]);
  if (p.rotating) s_.withdrawn += 0.5 * p.inertia(i) * p.w[i].squaredNorm();
}

void EnergyLedger::serialize(Archive& a) {
  // Doubles only. The friction terms after the first ones, and only when there is friction, so a
  // frictionless checkpoint keeps its layout.
  a.raw(&s_, offsetof(EnergyState, rotational));
  a & p_diss_prev_ & p_coh_prev_ & cohesion_inflow_ & mechanical_max_ & max_drift_;
  if (with_friction_) a & s_.rotational & s_.elastic_tangential & s_.elastic_rolling & s_.friction_dissipated & p_friction_prev_ & friction_work_;
}

}  // namespace silodem
