#include "silodem/probes/charge_probe.hpp"

#include <cmath>

#include <Eigen/Geometry>  // cross products
#include <iomanip>
#include <sstream>

#include "silodem/checkpoint/archive.hpp"
#include "silodem/output/checked_file.hpp"

namespace silodem {

ChargeProbe::ChargeProbe(const ProbeSpec& spec, const WallSpec& wall)
    : Probe(spec.name), spec_(spec),
      centre_(wall.motion && wall.motion->angular_speed != 0.0 ? wall.motion->centre : wall.centre) {}

ChargeSample ChargeProbe::measure(const Particles& p, double t) const {
  ChargeSample s;
  s.t = t;
  s.balls = long(p.n_mobile);
  Vec3 moment = Vec3::Zero();
  for (std::size_t i = 0; i < p.n_mobile; ++i) {
    s.mass += p.m[i];
    s.volume += 4.0 / 3.0 * kPi * p.r[i] * p.r[i] * p.r[i];
    moment += p.m[i] * p.x[i];
    s.angular_momentum += p.m[i] * (p.x[i] - centre_).cross(p.v[i]);
    s.kinetic += 0.5 * p.m[i] * p.v[i].squaredNorm();
    if (p.rotating) {
      s.angular_momentum += p.inertia(i) * p.w[i];
      s.kinetic += 0.5 * p.inertia(i) * p.w[i].squaredNorm();
    }
  }
  if (s.mass > 0.0) s.centre_of_mass = moment / s.mass;
  return s;
}

void ChargeProbe::sample(const Particles& p, double t) {
  last_ = measure(p, t);
  if (samples_++ == 0) first_ = last_;
  if (spec_.interval > 0.0 && t + 1e-15 >= next_row_) {
    rows_.push_back(last_);
    next_row_ = t + spec_.interval;
  }
  if (t + 1e-15 < spec_.from_time) return;
  if (window_samples_++ == 0) window_start_ = last_;
  com_sum_ += last_.mass * last_.centre_of_mass;
  mass_sum_ += last_.mass;
}

nlohmann::json ChargeProbe::write(const std::filesystem::path& dir) const {
  std::ostringstream out;
  out << std::setprecision(12) << "t,balls,mass,volume,x,y,z,lx,ly,lz,kinetic\n";
  for (const ChargeSample& s : rows_)
    out << s.t << ',' << s.balls << ',' << s.mass << ',' << s.volume << ',' << s.centre_of_mass.x() << ','
        << s.centre_of_mass.y() << ',' << s.centre_of_mass.z() << ',' << s.angular_momentum.x() << ','
        << s.angular_momentum.y() << ',' << s.angular_momentum.z() << ',' << s.kinetic << '\n';
  write_file_checked(dir / (name() + ".csv"), out.str());
  const auto vec = [](const Vec3& v) { return nlohmann::json{v.x(), v.y(), v.z()}; };
  const auto state = [&](const ChargeSample& s) {
    return nlohmann::json{{"t", s.t}, {"balls", s.balls}, {"mass", s.mass}, {"volume", s.volume},
                          {"centre_of_mass", vec(s.centre_of_mass)}, {"angular_momentum", vec(s.angular_momentum)},
                          {"kinetic", s.kinetic}};
  };
  nlohmann::json j = {{"type", "charge"}, {"file", name() + ".csv"}, {"about", vec(centre_)}, {"first", state(first_)},
                      {"final", state(last_)}};
  if (window_samples_ > 0 && mass_sum_ > 0.0)  // an empty vessel has no centre of mass
    j["window"] = {{"from_time", spec_.from_time}, {"samples", window_samples_}, {"start", state(window_start_)},
                   {"mean_mass", mass_sum_ / double(window_samples_)},
                   {"mean_centre_of_mass", vec(com_sum_ / mass_sum_)}};
  return j;
}

void ChargeProbe::serialize(Archive& a) {
  a & first_ & last_ & window_start_ & com_sum_ & mass_sum_ & samples_ & window_samples_ & next_row_ & rows_;
}

}  // namespace silodem
