#pragma once
// Section force probe: the force carried across a horizontal plane z = z_s, as the sum of the
// contact forces on every ball whose centre lies above it, mobile and fixed. Forces between two
// balls on the same side cancel in pairs, so the sum is exactly what the balls below exert on the
// balls above — the traction on the plane times its area, with no assumption about the walls
// (a shear box's upper ring, moving or not, is part of the body above). A row every `interval`.
#include <vector>

#include "silodem/checkpoint/archive.hpp"
#include "silodem/probes/probe.hpp"

namespace silodem {

class SectionForceProbe final : public Probe {
 public:
  explicit SectionForceProbe(const ProbeSpec& spec);
  void sample(const Particles& p, double t) override;
  nlohmann::json write(const std::filesystem::path& dir) const override;
  void serialize(Archive& a) override;

 private:
  struct Row {
    double t = 0.0;
    Vec3 force = Vec3::Zero();     // N, on the balls above from the balls below
    double mobile_above = 0.0;     // mobile balls above the plane
    double mobile_mass_above = 0.0;
    void serialize(Archive& a) { a & t & force & mobile_above & mobile_mass_above; }
  };
  ProbeSpec spec_;
  double next_row_ = 0.0;
  std::vector<Row> rows_;
};

}  // namespace silodem
