#include "silodem/probes/pair_probe.hpp"

#include "silodem/checkpoint/archive.hpp"
#include "silodem/output/checked_file.hpp"

#include <iomanip>
#include <sstream>

#include "silodem/contact/pair_constants.hpp"

namespace silodem {

PairProbe::PairProbe(const ProbeSpec& spec, bool clamp)
    : Probe(spec.name), a_(spec.balls.at(0)), b_(spec.balls.at(1)), clamp_(clamp) {}

void PairProbe::sample(const Particles& p, double t) {
  if (p.topology != topology_) {
    topology_ = p.topology;
    i_ = std::size_t(p.find(a_));
    j_ = std::size_t(p.find(b_));
    if (!detector_) {
      k_ = contact::series(p.k[i_], p.k[j_]);
      c_ = contact::series(p.c[i_], p.c[j_]);
      detector_.emplace(k_, c_, clamp_);
    }
  }
  const Vec3 d = p.x[i_] - p.x[j_];
  const double dist = d.norm();
  const double delta = p.r[i_] + p.r[j_] - dist;
  const double rate = -(p.v[i_] - p.v[j_]).dot(d / dist);
  detector_->sample(t, delta, rate);
}

nlohmann::json PairProbe::write(const std::filesystem::path& dir) const {
  std::ostringstream out;
  out << std::setprecision(17);
  out << "event,t_start,t_end,duration,rate_in,rate_out,restitution,max_overlap,ended\n";
  const auto& ev = detector_->events();
  for (std::size_t n = 0; n < ev.size(); ++n) {
    const auto& e = ev[n];
    // A value that does not exist is an empty cell, never nan or inf: an open contact has no end,
    // and one present from the first sample without approaching (rate_in <= 0) no restitution.
    out << n << ',' << e.t_start << ',';
    if (e.ended) out << e.t_end << ',' << e.duration();
    else out << ',';
    out << ',' << e.rate_in << ',';
    if (e.ended) out << e.rate_out;
    out << ',';
    if (e.ended && e.rate_in > 0.0) out << e.restitution();
    out << ',' << e.max_overlap << ',' << (e.ended ? 1 : 0) << '\n';
  }
  write_file_checked(dir / (name() + ".csv"), out.str());
  return {{"type", "pair"},
          {"balls", {a_, b_}},
          {"file", name() + ".csv"},
          {"k", k_},
          {"c", c_},
          {"events", ev.size()},
          {"final_overlap", detector_->last_delta()},
          {"final_overlap_rate", detector_->last_rate()},
          {"max_gap", detector_->max_gap()},
          {"max_gap_after_first_contact", detector_->max_gap_after_contact()}};
}

void PairProbe::serialize(Archive& a) {
  if (a.loading()) topology_ = ~std::uint64_t(0);  // looked up again by id
  a & k_ & c_;
  bool has = detector_.has_value();
  a & has;
  if (a.loading()) {
    detector_.reset();
    if (has) detector_.emplace(k_, c_, clamp_);
  }
  if (has) a & *detector_;
}

}  // namespace silodem
