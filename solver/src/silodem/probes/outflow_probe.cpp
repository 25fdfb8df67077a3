#include "silodem/probes/outflow_probe.hpp"

#include "silodem/checkpoint/archive.hpp"
#include "silodem/output/checked_file.hpp"

#include <iomanip>
#include <sstream>

namespace silodem {

nlohmann::json OutflowProbe::write(const std::filesystem::path& dir) const {
  std::ostringstream out;
  out << std::setprecision(17) << "t,id,mass,cumulative_mass,x,y,z\n";
  double total = 0.0;
  for (const auto& e : exits_) {
    total += e.mass;
    out << e.t << ',' << e.id << ',' << e.mass << ',' << total << ',' << e.x.x() << ',' << e.x.y() << ',' << e.x.z() << '\n';
  }
  write_file_checked(dir / (name() + ".csv"), out.str());
  return {{"type", "outflow"}, {"file", name() + ".csv"}, {"exits", exits_.size()}, {"mass", total}};
}

void OutflowProbe::serialize(Archive& a) { a & exits_; }

}  // namespace silodem
