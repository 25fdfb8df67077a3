#pragma once
// Particle dumps in LAMMPS's text "dump custom" layout, so the harness reads every code's states —
// this solver's, LAMMPS's, LIGGGHTS's and YADE's — with one reader and rebuilds the energy ledger
// and the probes from them the same way.
#include <filesystem>

#include "silodem/output/checked_file.hpp"

#include "silodem/scene/particles.hpp"

namespace silodem {

/// Columns written (and expected by the harness): id mass radius x y z vx vy vz fx fy fz fixed.
/// f is the contact force (on wall balls: the wall load); fixed is 1 for a wall ball — balls stopped
/// at a gate closure turn fixed mid-run, so the flag travels with every frame.
class DumpWriter {
 public:
  explicit DumpWriter(const std::filesystem::path& file);
  /// A restart: the file cut back to `bytes` (what it held at the checkpoint), then appended to.
  DumpWriter(const std::filesystem::path& file, std::uintmax_t bytes);
  /// Bytes written so far, flushed (recorded in a checkpoint).
  std::uintmax_t flushed_bytes();
  void frame(long step, const Particles& p);
  /// Flushes and closes, checked (before the directory is published).
  void close() { out_.close(); }

 private:
  CheckedFile out_;
};

}  // namespace silodem
