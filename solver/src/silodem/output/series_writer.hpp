#pragma once
// The time-series CSV every run writes (and every reference-code adapter will write): one row per
// output interval with the energy ledger, the ball count and the wall-force resultant.
#include <filesystem>

#include "silodem/output/checked_file.hpp"

#include "silodem/energy/energy_ledger.hpp"
#include "silodem/forces/force_field.hpp"
#include "silodem/scene/particles.hpp"

namespace silodem {

class SeriesWriter {
 public:
  explicit SeriesWriter(const std::filesystem::path& file);
  /// A restart: the file cut back to `bytes` (what it held at the checkpoint), then appended to.
  SeriesWriter(const std::filesystem::path& file, std::uintmax_t bytes);
  /// Bytes written so far, flushed (recorded in a checkpoint).
  std::uintmax_t flushed_bytes();
  void row(const EnergyState& e, const Particles& p, const ForceTotals& t);
  /// The same row from its parts: the mobile count and the walls' resultant (a partitioned run's
  /// whole scene, mpi/domain.hpp).
  void row(const EnergyState& e, std::size_t n_mobile, const Vec3& wall_force, const ForceTotals& t);
  /// Flushes and closes, checked (before the directory is published).
  void close() { out_.close(); }

 private:
  CheckedFile out_;
};

/// Σ of the contact forces on all wall balls: the load the balls exert on the wall.
Vec3 wall_force_resultant(const Particles& p);

}  // namespace silodem
