#include "silodem/probes/wall_load_probe.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "silodem/checkpoint/archive.hpp"
#include "silodem/forces/surface_contacts.hpp"
#include "silodem/output/checked_file.hpp"

namespace silodem {

WallLoadProbe::WallLoadProbe(const ProbeSpec& spec, const WallSpec& wall)
    : Probe(spec.name), spec_(spec), wall_(wall.name),
      centre_(wall.motion && wall.motion->angular_speed != 0.0 ? wall.motion->centre : wall.centre) {}

WallLoadProbe::WallLoadProbe(const ProbeSpec& spec, const SurfaceContacts& surfaces)
    : Probe(spec.name), spec_(spec), wall_(spec.wall), centre_(Vec3::Zero()), topology_(0), surfaces_(&surfaces) {
  for (std::size_t k = 0; k < surfaces.surfaces().size(); ++k)
    if (surface_of(surfaces.surfaces()[k].name, wall_)) index_.push_back(k);
  if (index_.empty()) throw std::logic_error("wall_load probe: no surface named " + wall_);
  centre_ = surfaces.surfaces()[index_.front()].centre;  // a profile's segments share their axis
}

WallLoadProbe::Load WallLoadProbe::measure(const Particles& p) {
  if (surfaces_) {
    Load l;
    for (const std::size_t k : index_) {
      const Surface& s = surfaces_->surfaces()[k];
      l.force += surfaces_->loads()[k];
      l.torque += surfaces_->torques()[k];
      l.power -= s.angular_speed * s.axis.dot(surfaces_->torques()[k]);
    }
    return l;
  }
  if (p.topology != topology_) {
    topology_ = p.topology;
    index_.clear();
    const std::string prefix = wall_ + "_";
    for (std::size_t i = p.n_mobile; i < p.size(); ++i)
      if (p.id[i].rfind(prefix, 0) == 0) index_.push_back(i);
  }
  Load l;
  for (const std::size_t i : index_) {
    l.force += p.f[i];
    l.torque += (p.x[i] - centre_).cross(p.f[i]);
    l.power -= p.f[i].dot(p.v[i]);
    if (p.rotating) {
      l.torque += p.t[i];
      l.power -= p.t[i].dot(p.w[i]);
    }
  }
  return l;
}

void WallLoadProbe::sample(const Particles& p, double t) {
  last_ = measure(p);
  if (spec_.interval > 0.0 && t + 1e-15 >= next_row_) {
    rows_.emplace_back(t, last_);
    next_row_ = t + spec_.interval;
  }
  if (t + 1e-15 < spec_.from_time || (spec_.to_time > 0.0 && t > spec_.to_time + 1e-15)) return;
  ++samples_;
  torque_max_ = std::max(torque_max_, last_.torque.norm());
  sum_.force += last_.force;
  sum_.torque += last_.torque;
  sum_.power += last_.power;
}

nlohmann::json WallLoadProbe::write(const std::filesystem::path& dir) const {
  std::ostringstream out;
  out << std::setprecision(12) << "t,fx,fy,fz,tx,ty,tz,power\n";
  for (const auto& [t, l] : rows_)
    out << t << ',' << l.force.x() << ',' << l.force.y() << ',' << l.force.z() << ',' << l.torque.x() << ','
        << l.torque.y() << ',' << l.torque.z() << ',' << l.power << '\n';
  write_file_checked(dir / (name() + ".csv"), out.str());
  const double n = samples_ > 0 ? double(samples_) : 1.0;
  const auto vec = [](const Vec3& v) { return nlohmann::json{v.x(), v.y(), v.z()}; };
  return {{"type", "wall_load"},
          {"wall", wall_},
          {"file", name() + ".csv"},
          {"wall_balls", index_.size()},
          {"torque_about", vec(centre_)},
          {"samples", samples_},
          {"from_time", spec_.from_time},
          {"to_time", spec_.to_time},
          {"force_mean", vec(sum_.force / n)},
          {"torque_mean", vec(sum_.torque / n)},
          {"torque_abs_max", torque_max_},
          {"power_mean", sum_.power / n},
          {"force_final", vec(last_.force)},
          {"torque_final", vec(last_.torque)}};
}

void WallLoadProbe::serialize(Archive& a) {
  a & sum_ & last_ & torque_max_ & samples_ & next_row_ & rows_;
  if (a.loading() && !surfaces_) topology_ = ~std::uint64_t(0);  // the wall's balls are found again
}

}  // namespace silodem
