#include "silodem/probes/section_force_probe.hpp"

#include "silodem/checkpoint/archive.hpp"
#include "silodem/output/checked_file.hpp"

#include <iomanip>
#include <sstream>

namespace silodem {

SectionForceProbe::SectionForceProbe(const ProbeSpec& spec) : Probe(spec.name), spec_(spec), next_row_(spec.from_time) {}

void SectionForceProbe::sample(const Particles& p, double t) {
  if (t + 1e-15 < next_row_) return;
  Row row;
  row.t = t;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!(p.x[i].z() > spec_.plane_z)) continue;
    row.force += p.f[i];
    if (!p.fixed(i)) row.mobile_above += 1.0, row.mobile_mass_above += p.m[i];
  }
  rows_.push_back(row);
  next_row_ = t + spec_.interval;
}

nlohmann::json SectionForceProbe::write(const std::filesystem::path& dir) const {
  std::ostringstream out;
  out << std::setprecision(12) << "t,fx,fy,fz,mobile_above,mobile_mass_above\n";
  for (const Row& r : rows_)
    out << r.t << ',' << r.force.x() << ',' << r.force.y() << ',' << r.force.z() << ',' << r.mobile_above << ','
        << r.mobile_mass_above << '\n';
  write_file_checked(dir / (name() + ".csv"), out.str());
  const Vec3 last = rows_.empty() ? Vec3::Zero() : rows_.back().force;
  return {{"type", "section_force"}, {"file", name() + ".csv"},  {"z", spec_.plane_z},
          {"interval", spec_.interval},  {"rows", rows_.size()}, {"force_final", {last.x(), last.y(), last.z()}}};
}

void SectionForceProbe::serialize(Archive& a) {
  a & next_row_ & rows_;
}

}  // namespace silodem
