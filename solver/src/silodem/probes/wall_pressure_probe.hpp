#pragma once
// Wall pressure probe: the force the balls exert on each ball of one wall, turned into pressure
// normal to the wall's nominal surface and wall shear, on a grid of (angle × height) cells of the
// unrolled cylinder — the paper's Fig. 7 — or (angle × radius) cells of a disk, (angle × slant)
// cells of a cone. A wall ball stands for the patch of nominal surface its bin covers: the cell's
// pressure is Σ (force on its balls · outward normal) / cell area. Averaged over time from
// `from_time`, and also reported for the final state. A wall in motion is binned in its own frame:
// a cell keeps its balls as the wall turns or shakes, and its normal turns with it. Each wall ball
// keeps the cell of its first location for the whole run (a wall moved by a stage event included),
// so the binning never depends on when the particle order changes.
#include <vector>

#include "silodem/checkpoint/archive.hpp"
#include "silodem/probes/probe.hpp"

namespace silodem {

class WallPressureProbe final : public Probe {
 public:
  WallPressureProbe(const ProbeSpec& spec, const WallSpec& wall);
  void sample(const Particles& p, double t) override;
  nlohmann::json write(const std::filesystem::path& dir) const override;
  void serialize(Archive& a) override;

 private:
  struct Cell {
    double area = 0.0;
    double normal_sum = 0.0, shear_sum = 0.0;   // time sums of Σ F·n and Σ F·t over the cell's balls
    double normal_last = 0.0, shear_last = 0.0;
    void serialize(Archive& a) { a.raw(this, sizeof *this); }  // doubles only
  };
  struct Placement {  // a wall ball's cell and directions, from where it was first located
    std::int64_t tag = 0;
    std::uint64_t cell = 0;
    Vec3 normal = Vec3::Zero(), tangent = Vec3::Zero();
    void serialize(Archive& a) { a & tag & cell & normal & tangent; }
  };
  void locate(const Particles& p, const Pose& q);
  Placement place(const Particles& p, std::size_t i, const Pose& q) const;
  ProbeSpec spec_;
  WallSpec wall_;
  std::uint64_t topology_ = ~std::uint64_t(0);
  std::vector<std::size_t> index_, cell_;       // wall balls and their cells
  std::vector<Vec3> normal_, tangent_;          // outward normal; shear direction (down the wall)
  std::vector<Placement> placements_;           // by tag, ascending
  std::vector<Cell> cells_;
  long samples_ = 0;
  Vec3 total_last_ = Vec3::Zero();
  double next_history_ = 0.0;
  std::vector<std::pair<double, std::vector<double>>> history_;  // (t, pressure per height band)
};

}  // namespace silodem
