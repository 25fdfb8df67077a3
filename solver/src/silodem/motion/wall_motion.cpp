#include "silodem/motion/wall_motion.hpp"

#include <unordered_map>

namespace silodem {

WallMotion::WallMotion(const CaseConfig& cfg, Particles& p) {
  std::unordered_map<std::string, Vec3> origin;
  if (!cfg.wall_reference.empty())
    for (const auto& [id, x0] : cfg.wall_reference) origin.emplace(id, x0);
  else
    for (const auto& b : cfg.balls)
      if (b.fixed) origin.emplace(b.id, b.position);
  for (const auto& w : cfg.walls) {
    if (!w.motion) continue;
    Driven d{w.name, *w.motion, {}, {}, {}};
    const std::string prefix = w.name + "_";
    for (std::size_t i = p.n_mobile; i < p.size(); ++i)
      if (p.id[i].rfind(prefix, 0) == 0) {
        const auto at = origin.find(p.id[i]);
        d.ids.push_back(p.id[i]);
        d.x0.push_back(at != origin.end() ? at->second : p.x[i]);
      }
    driven_.push_back(std::move(d));
  }
  if (!driven_.empty()) p.driven_walls = p.moving_walls = true;
}

void WallMotion::locate(const Particles& p) {
  topology_ = p.topology;
  owner_.assign(p.size(), -1);
  slot_.assign(p.size(), 0);
  std::unordered_map<std::string, std::size_t> where;
  for (std::size_t i = p.n_mobile; i < p.size(); ++i) where.emplace(p.id[i], i);
  for (std::size_t k = 0; k < driven_.size(); ++k) {
    Driven& d = driven_[k];
    d.index.assign(d.ids.size(), kNone);
    for (std::size_t s = 0; s < d.ids.size(); ++s)
      if (const auto at = where.find(d.ids[s]); at != where.end()) {
        d.index[s] = at->second;
        owner_[at->second] = std::int32_t(k);
        slot_[at->second] = std::uint32_t(s);
      }
  }
}

void WallMotion::place(Particles& p, double t) {
  if (driven_.empty()) return;
  if (p.topology != topology_) locate(p);
  for (const Driven& d : driven_) {
    const Pose q = pose_at(d.law, t);
    for (std::size_t s = 0; s < d.index.size(); ++s) {
      const std::size_t i = d.index[s];
      if (i == kNone) continue;
      p.x[i] = t < d.law.start_time ? d.x0[s] : moved_position(d.law, q, d.x0[s]);  // as built until it starts
      p.v[i] = wall_velocity(d.law, q, p.x[i]);
      if (p.rotating) p.w[i] = q.omega;
    }
  }
}

double WallMotion::advance(Particles& p, double t_next, double dt) {
  const double power = wall_power(p);
  if (!driven_.empty() && p.topology != topology_) locate(p);
  for (std::size_t i = p.n_mobile; i < p.size(); ++i)
    if ((driven_.empty() || owner_[i] < 0) && !p.v[i].isZero()) p.x[i] += dt * p.v[i];
  place(p, t_next);
  return power;
}

const MotionLaw* WallMotion::law(const std::string& wall) const {
  for (const Driven& d : driven_)
    if (d.wall == wall) return &d.law;
  return nullptr;
}

Vec3 WallMotion::reference_position(const Particles& p, std::size_t i) {
  if (driven_.empty()) return p.x[i];
  if (p.topology != topology_) locate(p);
  return owner_[i] < 0 ? p.x[i] : driven_[std::size_t(owner_[i])].x0[slot_[i]];
}

double wall_power(const Particles& p) {
  double power = 0.0;
  for (std::size_t i = p.n_mobile; i < p.size(); ++i) power -= p.f[i].dot(p.v[i]);
  if (p.rotating)
    for (std::size_t i = p.n_mobile; i < p.size(); ++i) power -= p.t[i].dot(p.w[i]);
  return power;
}

}  // namespace silodem
