#include "silodem/probes/area_fraction_probe.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "silodem/output/checked_file.hpp"

namespace silodem {

AreaFractionProbe::AreaFractionProbe(const ProbeSpec& spec)
    : Probe(spec.name), spec_(spec), next_sample_(spec.from_time),
      area_(std::size_t(spec.radial_bins) * std::size_t(spec.height_bins), 0.0) {}

void AreaFractionProbe::sample(const Particles& p, double t) {
  if (t + 1e-15 < next_sample_ || (spec_.to_time > 0.0 && t > spec_.to_time + 1e-15)) return;
  next_sample_ += spec_.interval * std::floor((t + 1e-15 - next_sample_) / spec_.interval + 1.0);
  frames_ += 1.0;
  const double dx = (spec_.field_x[1] - spec_.field_x[0]) / spec_.radial_bins;
  const double dz = (spec_.field_z[1] - spec_.field_z[0]) / spec_.height_bins;
  for (std::size_t i = 0; i < p.n_mobile; ++i) {
    const double fx = (p.x[i].x() - spec_.field_x[0]) / dx, fz = (p.x[i].z() - spec_.field_z[0]) / dz;
    if (!(fx >= 0.0 && fx < spec_.radial_bins && fz >= 0.0 && fz < spec_.height_bins)) continue;
    area_[std::size_t(fz) * std::size_t(spec_.radial_bins) + std::size_t(fx)] += kPi * p.r[i] * p.r[i];
  }
}

nlohmann::json AreaFractionProbe::write(const std::filesystem::path& dir) const {
  const double dx = (spec_.field_x[1] - spec_.field_x[0]) / spec_.radial_bins;
  const double dz = (spec_.field_z[1] - spec_.field_z[0]) / spec_.height_bins;
  std::ostringstream out;
  out << std::setprecision(12) << "ix,iz,x,z,area_fraction\n";
  double covered = 0.0;
  for (int iz = 0; iz < spec_.height_bins; ++iz)
    for (int ix = 0; ix < spec_.radial_bins; ++ix) {
      const double a = area_[std::size_t(iz) * std::size_t(spec_.radial_bins) + std::size_t(ix)];
      covered += a;
      out << ix << ',' << iz << ',' << spec_.field_x[0] + (ix + 0.5) * dx << ',' << spec_.field_z[0] + (iz + 0.5) * dz << ','
          << (frames_ > 0.0 ? a / (frames_ * dx * dz) : 0.0) << '\n';
    }
  write_file_checked(dir / (name() + ".csv"), out.str());
  const double total = (spec_.field_x[1] - spec_.field_x[0]) * (spec_.field_z[1] - spec_.field_z[0]);
  return {{"type", "area_fraction"}, {"file", name() + ".csv"}, {"samples", frames_},
          {"mean_area_fraction", frames_ > 0.0 ? covered / (frames_ * total) : 0.0}};
}

void AreaFractionProbe::serialize(Archive& a) { a & next_sample_ & frames_ & area_; }

}  // namespace silodem
