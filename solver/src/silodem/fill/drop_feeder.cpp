#include "silodem/fill/drop_feeder.hpp"

#include "silodem/checkpoint/archive.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "silodem/fill/free_fall.hpp"

namespace silodem {

DropFeeder::DropFeeder(const DropSpec& spec, const Material& material, std::int32_t material_index,
                       const Vec3& gravity, std::uint64_t seed, std::int64_t first_tag)
    : spec_(spec),
      material_(material),
      material_index_(material_index),
      g_abs_(gravity.norm()),
      rng_(seed),
      first_tag_(first_tag) {}

Vec3 DropFeeder::draw_start() {
  if (!spec_.positions.empty())
    return Vec3(spec_.positions[std::size_t(attempted_)][0], spec_.positions[std::size_t(attempted_)][1], spec_.z0);
  const double x0 = rng_.uniform(spec_.x_min, spec_.x_max);
  const double y0 = rng_.uniform(spec_.y_min, spec_.y_max);
  return Vec3(x0, y0, spec_.z0);
}

double DropFeeder::draw_radius() { return spec_.r_min + (spec_.r_max - spec_.r_min) * rng_.uniform(); }

std::vector<DropRecord> DropFeeder::planned_releases() const {
  DropFeeder copy = *this;  // the same engine state: the same draws as the run will make
  std::vector<DropRecord> out;
  for (; copy.attempted_ < spec_.count; ++copy.attempted_) {
    DropRecord rec;
    rec.index = copy.attempted_;
    rec.start = copy.draw_start();
    rec.r = copy.draw_radius();
    rec.x = rec.start;
    rec.v = Vec3(0.0, 0.0, -spec_.release_speed);
    out.push_back(rec);
  }
  return out;
}

std::optional<DropRecord> DropFeeder::maybe_drop(Particles& p, long step, double t) {
  if ((done() && recycled_.empty()) || step % spec_.interval_steps != 0) return std::nullopt;
  if (spec_.release) return done() ? std::nullopt : release(p, t);
  // "Wait for settling": drop only while the fill height z_max (highest mobile centre) is below z0.
  double z_max = -INFINITY;
  for (std::size_t i = 0; i < p.n_mobile; ++i) z_max = std::max(z_max, p.x[i].z());
  if (!done() && !std::isnan(spec_.full_level) && surface_height(p) >= spec_.full_level) {
    full_ = true;
    full_time_ = t;
    if (recycled_.empty()) return std::nullopt;
  }
  if (z_max >= spec_.z0) return std::nullopt;

  DropRecord rec;
  rec.index = attempted_;
  rec.t = t;
  // Position (14) and radius (1); explicit positions replace the random inlet point.
  rec.start = draw_start();
  const bool recycling = !recycled_.empty();
  if (recycling) {
    rec.r = recycled_.front().r;
    rec.index = -1;
  } else {
    rec.r = draw_radius();
    ++attempted_;
  }

  const FirstContact fc = find_first_contact(p, rec.start, rec.r, g_abs_);
  if (fc.kind == FirstContact::Kind::NoObstacle) {
    rec.outcome = "no_obstacle";  // the ball would fall past everything: outside the silo
    return rec;
  }
  rec.obstacle_index = long(fc.obstacle);
  rec.obstacle_id = p.id[fc.obstacle];
  if (fc.kind == FirstContact::Kind::StartOverlaps) {
    rec.outcome = "start_overlaps";
    return rec;
  }
  if (fc.kind == FirstContact::Kind::PlacementOverlaps) {
    rec.outcome = "placement_overlaps";  // a ball still falling occupies the contact point: try later
    return rec;
  }
  rec.outcome = "placed";
  rec.h = fc.h;
  // Initial conditions (16): at the contact point, moving down at the free-fall speed, or at rest
  // (the paper's option for stability early in the fill).
  rec.x = rec.start - Vec3(0.0, 0.0, fc.h);
  rec.v = spec_.free_fall_velocity ? Vec3(0.0, 0.0, -std::sqrt(2.0 * g_abs_ * fc.h)) : Vec3::Zero();
  // Mass (Algorithm 2 line 27 prints γ/3 r³π; the sphere's volume is 4/3 π r³, docs/model.md §1).
  if (recycling) {
    Particles::Ball b = recycled_.front();
    recycled_.erase(recycled_.begin());
    b.x = rec.x;
    b.v = rec.v;
    rec.recycled_id = b.id;
    p.add(b, false);
    return rec;
  }
  add_new(p, rec);
  return rec;
}

void DropFeeder::add_new(Particles& p, const DropRecord& rec) {
  const double m = material_.density * 4.0 / 3.0 * kPi * rec.r * rec.r * rec.r;
  p.add({rec.x, rec.v, rec.r, m, material_.k, material_.c, material_index_, "drop" + std::to_string(rec.index),
         first_tag_ + rec.index},
        false);
  ++placed_;
}

std::optional<DropRecord> DropFeeder::release(Particles& p, double t) {
  // Recycled balls are not part of the planned sequence: the loader refuses recycling with release.
  DropRecord rec;
  rec.index = attempted_;
  rec.t = t;
  rec.start = draw_start();
  rec.r = draw_radius();
  ++attempted_;
  // A release point inside a ball would start with a blow-up overlap: refused, as in Algorithm 2
  // (the translation hands every code the whole sequence, so the comparison checks none was refused).
  for (std::size_t j = 0; j < p.size(); ++j)
    if ((p.x[j] - rec.start).squaredNorm() < (p.r[j] + rec.r) * (p.r[j] + rec.r)) {
      rec.outcome = "start_overlaps";
      rec.obstacle_index = long(j);
      rec.obstacle_id = p.id[j];
      return rec;
    }
  rec.outcome = "placed";
  rec.x = rec.start;
  rec.v = Vec3(0.0, 0.0, -spec_.release_speed);
  add_new(p, rec);
  return rec;
}

double DropFeeder::surface_height(const Particles& p) const {
  // Not z_max: balls placed at rest on balls placed at rest stand in short-lived towers far above
  // the bed (the zero-velocity option), which would end the fill at a fraction of the volume.
  // The median of the column tops over the inlet ignores a few towers.
  const double side = 4.0 * spec_.r_max;
  if (!spec_.positions.empty()) return std::numeric_limits<double>::quiet_NaN();  // no inlet to divide
  const double x0 = spec_.x_min, y0 = spec_.y_min;
  const long nx = std::max(1L, long(std::ceil((spec_.x_max - spec_.x_min) / side)));
  const long ny = std::max(1L, long(std::ceil((spec_.y_max - spec_.y_min) / side)));
  std::vector<double> top(std::size_t(nx * ny), -INFINITY);
  for (std::size_t i = 0; i < p.n_mobile; ++i) {
    const long ix = long(std::floor((p.x[i].x() - x0) / side)), iy = long(std::floor((p.x[i].y() - y0) / side));
    if (ix < 0 || iy < 0 || ix >= nx || iy >= ny) continue;
    double& t = top[std::size_t(iy * nx + ix)];
    t = std::max(t, p.x[i].z());
  }
  std::nth_element(top.begin(), top.begin() + long(top.size() / 2), top.end());
  return top[top.size() / 2];
}

void DropRecord::serialize(Archive& a) {
  a & index & recycled_id & t & start & r & outcome & h & obstacle_id & obstacle_index & x & v;
}

void DropFeeder::serialize(Archive& a) {
  std::string rng = rng_.state();
  a & rng & recycled_ & attempted_ & placed_ & full_ & full_time_;
  if (a.loading() && !rng_.set_state(rng)) throw CheckpointError("checkpoint payload is damaged (random engine state)");
  if (a.loading())
    for (const auto& b : recycled_)
      if (!b.x.allFinite() || !b.v.allFinite() || !(b.r > 0.0 && b.r < 1e3) || !(b.m > 0.0 && b.m < 1e30))
        throw CheckpointError("checkpoint payload is damaged (a recycled ball is not a ball)");
}

}  // namespace silodem
