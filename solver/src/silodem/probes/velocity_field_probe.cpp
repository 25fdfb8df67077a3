#include "silodem/probes/velocity_field_probe.hpp"

#include <cmath>
#include <iomanip>
#include <numbers>
#include <sstream>

#include "silodem/checkpoint/archive.hpp"
#include "silodem/output/checked_file.hpp"

namespace silodem {

VelocityFieldProbe::VelocityFieldProbe(const ProbeSpec& spec)
    : Probe(spec.name), spec_(spec), next_sample_(spec.from_time),
      cells_(std::size_t(spec.radial_bins) * std::size_t(spec.height_bins)) {}

void VelocityFieldProbe::sample(const Particles& p, double t) {
  if (t + 1e-15 < next_sample_ || (spec_.to_time > 0.0 && t > spec_.to_time + 1e-15)) return;
  const double dr = spec_.field_radius / spec_.radial_bins, dz = (spec_.field_z[1] - spec_.field_z[0]) / spec_.height_bins;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.fixed(i)) continue;
    const Vec3 d = p.x[i] - spec_.field_centre;
    const double r = std::hypot(d.x(), d.y()), z = p.x[i].z();
    if (!(r < spec_.field_radius) || !(z >= spec_.field_z[0] && z < spec_.field_z[1])) continue;
    const std::size_t ir = std::min(std::size_t(r / dr), std::size_t(spec_.radial_bins - 1));
    const std::size_t iz = std::min(std::size_t((z - spec_.field_z[0]) / dz), std::size_t(spec_.height_bins - 1));
    Cell& c = cells_[iz * std::size_t(spec_.radial_bins) + ir];
    c.samples += 1.0;
    c.vz += p.v[i].z();
    c.vr += r > 0.0 ? (p.v[i].x() * d.x() + p.v[i].y() * d.y()) / r : 0.0;
    c.volume += 4.0 / 3.0 * std::numbers::pi * p.r[i] * p.r[i] * p.r[i];
  }
  frames_ += 1.0;
  next_sample_ = t + spec_.interval;
}

nlohmann::json VelocityFieldProbe::write(const std::filesystem::path& dir) const {
  const double dr = spec_.field_radius / spec_.radial_bins, dz = (spec_.field_z[1] - spec_.field_z[0]) / spec_.height_bins;
  std::ostringstream out;
  out << std::setprecision(12) << "radial_bin,height_bin,r_centre,z_centre,samples,mean_vz,mean_vr,solid_fraction\n";
  for (int iz = 0; iz < spec_.height_bins; ++iz)
    for (int ir = 0; ir < spec_.radial_bins; ++ir) {
      const Cell& c = cells_[std::size_t(iz) * std::size_t(spec_.radial_bins) + std::size_t(ir)];
      const double ring = std::numbers::pi * dr * dr * (2.0 * ir + 1.0) * dz;  // the cell's volume
      out << ir << ',' << iz << ',' << (ir + 0.5) * dr << ',' << spec_.field_z[0] + (iz + 0.5) * dz << ',' << c.samples
          << ',' << (c.samples > 0 ? c.vz / c.samples : 0.0) << ',' << (c.samples > 0 ? c.vr / c.samples : 0.0) << ','
          << (frames_ > 0 ? c.volume / (frames_ * ring) : 0.0) << '\n';
    }
  write_file_checked(dir / (name() + ".csv"), out.str());
  const Vec3& o = spec_.field_centre;
  return {{"type", "velocity_field"}, {"file", name() + ".csv"}, {"centre", {o.x(), o.y(), o.z()}},
          {"radius", spec_.field_radius}, {"z", {spec_.field_z[0], spec_.field_z[1]}},
          {"radial_bins", spec_.radial_bins}, {"height_bins", spec_.height_bins}, {"frames", frames_}};
}

void VelocityFieldProbe::serialize(Archive& a) { a & next_sample_ & frames_ & cells_; }

}  // namespace silodem
