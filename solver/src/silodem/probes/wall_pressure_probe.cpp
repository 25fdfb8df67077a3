#include "silodem/probes/wall_pressure_probe.hpp"

#include "silodem/checkpoint/archive.hpp"
#include "silodem/output/checked_file.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace silodem {

namespace {
/// Where a point lies on the wall's nominal surface: (angle in [0, 2π), coordinate along the wall
/// in [0, 1]) and the surface's outward normal and down-slope tangent there.
struct SurfacePoint {
  double angle, along;
  Vec3 normal, tangent;
};

SurfacePoint surface_point(const WallSpec& w, const Vec3& x) {
  const Vec3 d = x - w.centre;
  double th = std::atan2(d.y(), d.x());
  if (th < 0.0) th += 2.0 * kPi;
  const Vec3 radial(std::cos(th), std::sin(th), 0.0);
  SurfacePoint s{th, 0.0, radial, Vec3(0, 0, -1)};
  if (w.type == "cylinder") {
    s.along = d.z() / w.height;  // 0 at the base, 1 at the top
  } else if (w.type == "disk") {
    const double r0 = 0.5 * w.hole_diameter, r1 = 0.5 * w.diameter;
    s.along = (std::hypot(d.x(), d.y()) - r0) / (r1 - r0);
    s.normal = Vec3(0, 0, -1);  // a bottom is pushed down
    s.tangent = radial;         // outward shear along the bottom
  } else {                      // cone: 0 at the outlet, 1 at the top rim
    const double r_top = 0.5 * w.diameter, r_bot = 0.5 * w.hole_diameter;
    const double slant = std::hypot(r_top - r_bot, w.height);
    s.along = (d.z() + w.height) / w.height;
    s.normal = (w.height / slant) * radial + Vec3(0, 0, -(r_top - r_bot) / slant);
    s.tangent = -((r_top - r_bot) / slant) * radial + Vec3(0, 0, -w.height / slant);  // down the slope
  }
  s.along = std::clamp(s.along, 0.0, 1.0);
  return s;
}

/// Area of the nominal surface between fractions a0 and a1 along the wall, over the full angle.
double band_area(const WallSpec& w, double a0, double a1) {
  if (w.type == "cylinder") return kPi * w.diameter * w.height * (a1 - a0);
  const double ra = 0.5 * w.hole_diameter, rb = 0.5 * w.diameter;
  const double r0 = ra + (rb - ra) * a0, r1 = ra + (rb - ra) * a1;
  if (w.type == "disk") return kPi * (r1 * r1 - r0 * r0);
  const double slant = std::hypot(rb - ra, w.height);
  return kPi * (r0 + r1) * slant * (a1 - a0);  // frustum mantle
}
}  // namespace

WallPressureProbe::WallPressureProbe(const ProbeSpec& spec, const WallSpec& wall)
    : Probe(spec.name), spec_(spec), wall_(wall) {
  cells_.resize(std::size_t(spec.angle_bins * spec.height_bins));
  for (int h = 0; h < spec.height_bins; ++h) {
    const double area = band_area(wall, double(h) / spec.height_bins, double(h + 1) / spec.height_bins) /
                        spec.angle_bins;
    for (int a = 0; a < spec.angle_bins; ++a) cells_[std::size_t(h * spec.angle_bins + a)].area = area;
  }
}

WallPressureProbe::Placement WallPressureProbe::place(const Particles& p, std::size_t i, const Pose& q) const {
  // In the wall's own frame: a moving wall's ball is binned where it sat at the law's origin.
  const MotionLaw* m = wall_.motion ? &*wall_.motion : nullptr;
  const Vec3 x0 = m ? Vec3(m->centre + q.rotation.transpose() * (p.x[i] - m->centre - q.shift)) : p.x[i];
  const SurfacePoint s = surface_point(wall_, x0);
  const int a = std::min(spec_.angle_bins - 1, int(s.angle / (2.0 * kPi) * spec_.angle_bins));
  const int h = std::min(spec_.height_bins - 1, int(s.along * spec_.height_bins));
  return {p.tag[i], std::uint64_t(h * spec_.angle_bins + a), s.normal, s.tangent};
}

void WallPressureProbe::locate(const Particles& p, const Pose& q) {
  index_.clear();
  cell_.clear();
  normal_.clear();
  tangent_.clear();
  const std::string prefix = wall_.name + "_";
  const auto by_tag = [](const Placement& e, std::int64_t tag) { return e.tag < tag; };
  for (std::size_t i = p.n_mobile; i < p.size(); ++i) {
    if (p.id[i].rfind(prefix, 0) != 0) continue;
    // A ball keeps its first placement: a wall moved by an event (the column's slip) would otherwise
    // change cells whenever the balls are renumbered.
    auto it = std::lower_bound(placements_.begin(), placements_.end(), p.tag[i], by_tag);
    if (it == placements_.end() || it->tag != p.tag[i]) it = placements_.insert(it, place(p, i, q));
    index_.push_back(i);
    cell_.push_back(std::size_t(it->cell));
    normal_.push_back(it->normal);
    tangent_.push_back(it->tangent);
  }
}

void WallPressureProbe::sample(const Particles& p, double t) {
  const Pose q = wall_.motion ? pose_at(*wall_.motion, t) : Pose{};
  if (p.topology != topology_) {
    topology_ = p.topology;
    locate(p, q);
  }
  const bool turns = wall_.motion && wall_.motion->angular_speed != 0.0;
  for (auto& c : cells_) c.normal_last = c.shear_last = 0.0;
  total_last_.setZero();
  for (std::size_t k = 0; k < index_.size(); ++k) {
    const Vec3& f = p.f[index_[k]];  // the force the balls exert on this wall ball
    Cell& c = cells_[cell_[k]];
    c.normal_last += turns ? f.dot(q.rotation * normal_[k]) : f.dot(normal_[k]);  // the directions turn with it
    c.shear_last += turns ? f.dot(q.rotation * tangent_[k]) : f.dot(tangent_[k]);
    total_last_ += f;
  }
  if (spec_.history_interval > 0.0 && t + 1e-15 >= next_history_) {
    // The pressure of each height band, averaged over the angle: Σ normal force / band area.
    std::vector<double> band(std::size_t(spec_.height_bins), 0.0);
    for (int h = 0; h < spec_.height_bins; ++h) {
      double f = 0.0, area = 0.0;
      for (int a = 0; a < spec_.angle_bins; ++a) {
        const Cell& c = cells_[std::size_t(h * spec_.angle_bins + a)];
        f += c.normal_last;
        area += c.area;
      }
      band[std::size_t(h)] = f / area;
    }
    history_.emplace_back(t, std::move(band));
    next_history_ = t + spec_.history_interval;
  }
  if (t + 1e-15 < spec_.from_time || (spec_.to_time > 0.0 && t > spec_.to_time + 1e-15)) return;
  ++samples_;
  for (auto& c : cells_) c.normal_sum += c.normal_last, c.shear_sum += c.shear_last;
}

nlohmann::json WallPressureProbe::write(const std::filesystem::path& dir) const {
  std::ostringstream out;
  out << std::setprecision(12)
      << "angle_bin,height_bin,angle_lo,angle_hi,along_lo,along_hi,area,pressure_mean,shear_mean,pressure_final,"
         "shear_final\n";
  const double n = samples_ > 0 ? double(samples_) : 1.0;
  for (int h = 0; h < spec_.height_bins; ++h)
    for (int a = 0; a < spec_.angle_bins; ++a) {
      const Cell& c = cells_[std::size_t(h * spec_.angle_bins + a)];
      out << a << ',' << h << ',' << 2.0 * kPi * a / spec_.angle_bins << ',' << 2.0 * kPi * (a + 1) / spec_.angle_bins
          << ',' << double(h) / spec_.height_bins << ',' << double(h + 1) / spec_.height_bins << ',' << c.area << ','
          << c.normal_sum / n / c.area << ',' << c.shear_sum / n / c.area << ',' << c.normal_last / c.area << ','
          << c.shear_last / c.area << '\n';
    }
  if (!history_.empty()) {
    std::ostringstream h;
    h << std::setprecision(12) << "t";
    for (int b = 0; b < spec_.height_bins; ++b) h << ",band" << b;
    h << '\n';
    for (const auto& [t, band] : history_) {
      h << t;
      for (double p : band) h << ',' << p;
      h << '\n';
    }
    write_file_checked(dir / (name() + "_history.csv"), h.str());
  }
  write_file_checked(dir / (name() + ".csv"), out.str());
  return {{"type", "wall_pressure"},
          {"history_file", history_.empty() ? "" : name() + "_history.csv"},
          {"wall", wall_.name},
          {"wall_type", wall_.type},
          {"file", name() + ".csv"},
          {"wall_balls", index_.size()},
          {"samples", samples_},
          {"from_time", spec_.from_time},
          {"to_time", spec_.to_time},
          {"force_final", {total_last_.x(), total_last_.y(), total_last_.z()}},
          {"geometry",
           {{"centre", {wall_.centre.x(), wall_.centre.y(), wall_.centre.z()}},
            {"diameter", wall_.diameter},
            {"height", wall_.height},
            {"hole_diameter", wall_.hole_diameter}}}};
}

void WallPressureProbe::serialize(Archive& a) {
  const std::size_t n_cells = cells_.size();
  a & cells_ & samples_ & total_last_ & next_history_ & history_ & placements_;
  if (!a.loading()) return;
  const bool cells_known = std::all_of(placements_.begin(), placements_.end(), [&](const Placement& e) { return e.cell < n_cells; });
  if (cells_.size() != n_cells || !cells_known) throw CheckpointError("checkpoint payload is damaged (wall pressure probe " + name() + ")");
  topology_ = ~std::uint64_t(0);  // the wall balls are located again, in the same order
}

}  // namespace silodem
