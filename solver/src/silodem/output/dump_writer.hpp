#pragma once
// Particle dumps in LAMMPS's text "dump custom" layout, so the harness reads every code's states —
// this solver's, LAMMPS's, LIGGGHTS's and YADE's — with one reader and rebuilds the energy ledger
// and the probes from them the same way.
#include <fstream>
#include <filesystem>

#include "silodem/scene/particles.hpp"

namespace silodem {

/// Columns written (and expected by the harness): id mass radius x y z vx vy vz fx fy fz fixed.
/// f is the contact force (on wall balls: the wall load); fixed is 1 for a wall ball — balls stopped
/// at a gate closure turn fixed mid-run, so the flag travels with every frame.
class DumpWriter {
 public:
  explicit DumpWriter(const std::filesystem::path& file);
  void frame(long step, const Particles& p);

 private:
  std::ofstream out_;
};

}  // namespace silodem
