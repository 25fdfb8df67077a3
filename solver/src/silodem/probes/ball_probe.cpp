#include "silodem/probes/ball_probe.hpp"

#include "silodem/checkpoint/archive.hpp"
#include "silodem/output/checked_file.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace silodem {

BallProbe::BallProbe(const ProbeSpec& spec, const Vec3& gravity, bool rotating)
    : Probe(spec.name), id_(spec.balls.at(0)), g_abs_(gravity.norm()), rotating_(rotating), from_time_(spec.from_time) {
  up_ = g_abs_ > 0.0 ? Vec3(-gravity / g_abs_) : Vec3(0.0, 0.0, 1.0);
}

void BallProbe::sample(const Particles& p, double t) {
  if (p.topology != topology_) {
    topology_ = p.topology;
    i_ = std::size_t(p.find(id_));
  }
  const double h = p.x[i_].dot(up_), w = p.v[i_].dot(up_);
  if (started_ && w_prev_ > 0.0 && w <= 0.0) {
    // The apex inside the step, assuming free flight over it (exact for a ballistic arc).
    const double rise = g_abs_ > 0.0 ? w_prev_ * w_prev_ / (2.0 * g_abs_) : 0.0;
    apexes_.emplace_back(t_prev_ + (g_abs_ > 0.0 ? w_prev_ / g_abs_ : 0.0), h_prev_ + rise);
  }
  started_ = true;
  t_prev_ = t;
  h_prev_ = h;
  w_prev_ = w;
  x_last_ = p.x[i_];
  v_last_ = p.v[i_];
  if (rotating_) w_last_ = p.w[i_];
  if (from_time_ > 0.0 && t + 1e-15 >= from_time_) {
    if (window_samples_++ == 0) t_start_ = t, x_start_ = x_last_, v_start_ = v_last_, w_start_ = w_last_;
    x_sum_ += x_last_;
  }
}

nlohmann::json BallProbe::write(const std::filesystem::path& dir) const {
  std::ostringstream out;
  out << std::setprecision(17) << "apex,t,height\n";
  for (std::size_t n = 0; n < apexes_.size(); ++n) out << n << ',' << apexes_[n].first << ',' << apexes_[n].second << '\n';
  write_file_checked(dir / (name() + ".csv"), out.str());
  nlohmann::json j = {{"type", "ball"},
                      {"ball", id_},
                      {"file", name() + ".csv"},
                      {"apexes", apexes_.size()},
                      {"final_position", {x_last_.x(), x_last_.y(), x_last_.z()}},
                      {"final_velocity", {v_last_.x(), v_last_.y(), v_last_.z()}}};
  if (rotating_) j["final_angular_velocity"] = {w_last_.x(), w_last_.y(), w_last_.z()};
  if (from_time_ > 0.0) {
    const auto vec = [](const Vec3& v) { return nlohmann::json{v.x(), v.y(), v.z()}; };
    j["window"] = {{"start_time", t_start_},
                   {"samples", window_samples_},
                   {"start_position", vec(x_start_)},
                   {"start_velocity", vec(v_start_)},
                   {"mean_position", vec(x_sum_ / double(std::max(window_samples_, 1L)))}};
    if (rotating_) j["window"]["start_angular_velocity"] = vec(w_start_);
  }
  return j;
}

void BallProbe::serialize(Archive& a) {
  if (a.loading()) topology_ = ~std::uint64_t(0);  // looked up again by id
  a & started_ & t_prev_ & h_prev_ & w_prev_ & apexes_ & x_last_ & v_last_;
  if (rotating_) a & w_last_;  // a frictionless checkpoint keeps its layout
  if (from_time_ > 0.0) a & window_samples_ & t_start_ & x_start_ & v_start_ & w_start_ & x_sum_;
}

}  // namespace silodem
