#include "silodem/energy/energy_ledger.hpp"

#include "silodem/checkpoint/archive.hpp"
#include "silodem/core/parallel.hpp"

#include <algorithm>
#include <cmath>

namespace silodem {

void EnergyLedger::totals(const Particles& p, const ForceTotals& t) {
  // Per chunk, then over chunks in order: the same bits for any thread count (core/parallel.hpp).
  const std::size_t chunks = sum_chunks(p.n_mobile);
  chunk_sums_.resize(2 * chunks);
  const long nc = long(chunks);
  SILODEM_PARALLEL_FOR
  for (long cl = 0; cl < nc; ++cl) {
    double kin = 0.0, grav = 0.0;
    const std::size_t end = std::min(p.n_mobile, (std::size_t(cl) + 1) * kSumChunk);
    for (std::size_t i = std::size_t(cl) * kSumChunk; i < end; ++i) {
      kin += 0.5 * p.m[i] * p.v[i].squaredNorm();
      grav -= p.m[i] * g_.dot(p.x[i]);
    }
    chunk_sums_[2 * std::size_t(cl)] = kin;
    chunk_sums_[2 * std::size_t(cl) + 1] = grav;
  }
  s_.kinetic = 0.0;
  s_.gravitational = 0.0;
  for (std::size_t c = 0; c < chunks; ++c) {
    s_.kinetic += chunk_sums_[2 * c];
    s_.gravitational += chunk_sums_[2 * c + 1];
  }
  s_.elastic = t.elastic_contact + t.elastic_cohesion;
  // Energy that flowed into cohesion springs, minus what they hold now, is what springs carried
  // away when they let go (zone exit, or the pair turning to approach): no per-pair history needed.
  s_.cohesion_removed = cohesion_inflow_ - t.elastic_cohesion;
  mechanical_max_ = std::max(mechanical_max_, s_.kinetic + s_.elastic);
  s_.scale = mechanical_max_ + s_.dissipated + cohesion_inflow_;
  s_.balance = s_.kinetic + s_.gravitational + s_.elastic + s_.dissipated + s_.cohesion_removed - s_.initial -
               s_.injected + s_.withdrawn;
  max_drift_ = std::max(max_drift_, std::abs(s_.relative_drift()));
}

void EnergyLedger::start(const Particles& p, const ForceTotals& t, double time) {
  s_ = EnergyState{};
  s_.t = time;
  cohesion_inflow_ = t.elastic_cohesion;
  p_diss_prev_ = t.p_dissipated;
  p_coh_prev_ = t.p_cohesion;
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
  p_diss_prev_ = t.p_dissipated;
  p_coh_prev_ = t.p_cohesion;
  totals(p, t);
}

void EnergyLedger::inject(double m, const Vec3& x, const Vec3& v) {
  s_.injected += 0.5 * m * v.squaredNorm() - m * g_.dot(x);
}

nlohmann::json EnergyLedger::summary() const {
  return {{"kinetic", s_.kinetic},
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
}

void EnergyLedger::withdraw(double m, const Vec3& x, const Vec3& v) {
  s_.withdrawn += 0.5 * m * v.squaredNorm() - m * g_.dot(x);
}

void EnergyLedger::serialize(Archive& a) {
  a.raw(&s_, sizeof s_);  // doubles only
  a & p_diss_prev_ & p_coh_prev_ & cohesion_inflow_ & mechanical_max_ & max_drift_;
}

}  // namespace silodem
