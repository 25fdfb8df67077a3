#include "silodem/probes/drops_probe.hpp"

#include "silodem/checkpoint/archive.hpp"
#include "silodem/output/checked_file.hpp"

#include <iomanip>
#include <sstream>

namespace silodem {

nlohmann::json DropsProbe::write(const std::filesystem::path& dir) const {
  std::ostringstream out;
  out << std::setprecision(17) << "drop,t,x0,y0,z0,r,outcome,h,obstacle,x,y,z,vx,vy,vz\n";
  long placed = 0;
  for (const auto& d : records_) {
    placed += d.outcome == "placed";
    out << d.index << ',' << d.t << ',' << d.start.x() << ',' << d.start.y() << ',' << d.start.z() << ',' << d.r
        << ',' << d.outcome << ',' << d.h << ',' << d.obstacle_id << ',' << d.x.x() << ',' << d.x.y() << ','
        << d.x.z() << ',' << d.v.x() << ',' << d.v.y() << ',' << d.v.z() << '\n';
  }
  write_file_checked(dir / (name() + ".csv"), out.str());
  return {{"type", "drops"}, {"file", name() + ".csv"}, {"attempted", records_.size()}, {"placed", placed}};
}

void DropsProbe::serialize(Archive& a) { a & records_; }

}  // namespace silodem
