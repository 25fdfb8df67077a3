#pragma once
// Particle snapshots for ParaView (VTK XML PolyData, appended raw binary: 48 bytes a ball in
// Float32, 92 in Float64, against about 250 as full-precision ASCII): every `interval`
// steps, vtk/balls_<step>.vtp holds the mobile balls and vtk/walls_<step>.vtp the wall balls —
// points with radius, mass, velocity, force (on a wall ball: the load the balls put on it) and
// the dump tag — and at the end vtk/balls.pvd and vtk/walls.pvd list them with their times, so
// ParaView opens each as one time series (render the points with the Glyph filter, Sphere glyph,
// scaled by "radius", scale factor 2; the points carry no vertex cells, which would cost 8 bytes a
// ball more). Written by hand: the format is a few lines of XML, and the
// test reads every file back with VTK's own reader (tests/solver/output/vtk_writer_test.cpp).
#include <filesystem>

#include "silodem/scene/particles.hpp"

namespace silodem {

class VtkWriter {
 public:
  /// Creates `dir` (DIR/vtk); `dt` turns steps into the times of the collections.
  /// `float64`: every real at full precision (the final frame equals state.sds bit for bit).
  VtkWriter(std::filesystem::path dir, double dt, bool float64);
  void frame(long step, const Particles& p) const;
  /// Writes the two .pvd collections from the frames found in the directory (so a restarted run,
  /// whose earlier frames came from before the kill, lists them all).
  void finish() const;

 private:
  std::filesystem::path dir_;
  double dt_;
  bool float64_;
};

}  // namespace silodem
