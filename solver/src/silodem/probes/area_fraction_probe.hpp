#pragma once
// Area fraction probe (the planar mode): the time-mean fraction of a rectangle of the x–z plane
// that the discs cover, on a grid of cells — where a vibrated bed compacts and where it loosens
// (seed 001's tray). Every `interval` s in [from_time, to_time] each mobile disc adds its area πr²
// to the cell that holds its centre; a cell's fraction is that sum over the samples, divided by the
// cell's area and the sample count. Counting whole discs by their centres is exact on average over
// cells much wider than a disc, and off by up to a disc's share at a cell's edge.
#include <vector>

#include "silodem/checkpoint/archive.hpp"
#include "silodem/probes/probe.hpp"

namespace silodem {

class AreaFractionProbe final : public Probe {
 public:
  explicit AreaFractionProbe(const ProbeSpec& spec);
  void sample(const Particles& p, double t) override;
  nlohmann::json write(const std::filesystem::path& dir) const override;
  void serialize(Archive& a) override;

 private:
  ProbeSpec spec_;
  double next_sample_ = 0.0;
  double frames_ = 0.0;
  std::vector<double> area_;  // per cell (height bin major), m² summed over samples
};

}  // namespace silodem
