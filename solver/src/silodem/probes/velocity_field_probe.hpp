#pragma once
// Velocity field probe: the time-mean velocity of the mobile grains on an axisymmetric grid of
// rings (r, z) about a vertical axis — the velocity section a silo engineer reads a flow pattern
// from (mass flow: the grains next to the hopper wall move; funnel flow: they rest while a channel
// above the outlet flows). Every `interval` s in [from_time, to_time] each grain whose centre lies
// in a cell adds its axial and radial velocity and its volume to the cell.
#include <vector>

#include "silodem/checkpoint/archive.hpp"
#include "silodem/probes/probe.hpp"

namespace silodem {

class VelocityFieldProbe final : public Probe {
 public:
  explicit VelocityFieldProbe(const ProbeSpec& spec);
  void sample(const Particles& p, double t) override;
  nlohmann::json write(const std::filesystem::path& dir) const override;
  void serialize(Archive& a) override;

 private:
  struct Cell {
    double samples = 0.0;  // grain-samples
    double vz = 0.0;       // sums over them, m/s
    double vr = 0.0;
    double volume = 0.0;   // m^3, for the solid fraction
    void serialize(Archive& a) { a & samples & vz & vr & volume; }
  };
  ProbeSpec spec_;
  double next_sample_ = 0.0;
  double frames_ = 0.0;
  std::vector<Cell> cells_;  // height bin major
};

}  // namespace silodem
