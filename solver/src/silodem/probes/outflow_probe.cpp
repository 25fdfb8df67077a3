#include "silodem/probes/outflow_probe.hpp"

#include "silodem/checkpoint/archive.hpp"

#include <fstream>
#include <iomanip>

namespace silodem {

nlohmann::json OutflowProbe::write(const std::filesystem::path& dir) const {
  std::ofstream out(dir / (name() + ".csv"));
  out << std::setprecision(17) << "t,id,mass,cumulative_mass\n";
  double total = 0.0;
  for (const auto& e : exits_) {
    total += e.mass;
    out << e.t << ',' << e.id << ',' << e.mass << ',' << total << '\n';
  }
  return {{"type", "outflow"}, {"file", name() + ".csv"}, {"exits", exits_.size()}, {"mass", total}};
}

void OutflowProbe::serialize(Archive& a) { a & exits_; }

}  // namespace silodem
