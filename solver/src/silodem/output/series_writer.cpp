#include "silodem/output/series_writer.hpp"

#include "silodem/checkpoint/checkpoint_file.hpp"

#include <iomanip>
#include <sstream>

namespace silodem {

Vec3 wall_force_resultant(const Particles& p) {
  Vec3 f = Vec3::Zero();
  for (std::size_t i = p.n_mobile; i < p.size(); ++i) f += p.f[i];
  return f;
}

SeriesWriter::SeriesWriter(const std::filesystem::path& file) : out_(file) {
  out_.write("t,E_kin,E_grav,E_el,E_diss,E_coh,E_in,balance,rel_drift,n_mobile,contacts,max_overlap_ratio,"
          "wall_fx,wall_fy,wall_fz\n");
}

namespace {
const std::filesystem::path& resumed(const std::filesystem::path& file, std::uintmax_t bytes) {
  resume_file(file, bytes);
  return file;
}
}  // namespace

SeriesWriter::SeriesWriter(const std::filesystem::path& file, std::uintmax_t bytes) : out_(resumed(file, bytes), true) {}

std::uintmax_t SeriesWriter::flushed_bytes() { return out_.flush(); }

void SeriesWriter::row(const EnergyState& e, const Particles& p, const ForceTotals& t) {
  row(e, p.n_mobile, wall_force_resultant(p), t);
}

void SeriesWriter::row(const EnergyState& e, std::size_t n_mobile, const Vec3& w, const ForceTotals& t) {
  std::ostringstream line;
  line << std::setprecision(12) << e.t << ',' << e.kinetic << ',' << e.gravitational << ',' << e.elastic << ',' << e.dissipated << ','
       << e.cohesion_removed << ',' << e.injected << ',' << e.balance << ',' << e.relative_drift() << ','
       << n_mobile << ',' << t.contacts << ',' << t.max_overlap_ratio << ',' << w.x() << ',' << w.y() << ','
       << w.z() << '\n';
  out_.write(line.str());
}

}  // namespace silodem
