#pragma once
// Streams frames of a LAMMPS-style text dump ("dump custom"): the format this solver, LAMMPS and
// LIGGGHTS write natively and the YADE driver imitates.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "silodem/core/types.hpp"

namespace harness {

struct DumpAtom {
  std::int64_t id = 0;
  double mass = 0.0, radius = 0.0;
  silodem::Vec3 x, v, f;
  silodem::Vec3 w = silodem::Vec3::Zero();  // angular velocity, columns omegax..omegaz (zero if not dumped)
  bool has_w = false;
  int fixed = -1;  // column "fixed" (or LAMMPS's "v_fixed"): 1 wall ball, 0 mobile, -1 not dumped
};

struct DumpFrame {
  long step = 0;
  std::vector<DumpAtom> atoms;
};

class DumpReader {
 public:
  explicit DumpReader(const std::filesystem::path& file);
  /// Reads the next frame; false at the end. Throws on a malformed frame, naming the line.
  bool next(DumpFrame& frame);

 private:
  std::ifstream in_;
  std::filesystem::path file_;
  long line_ = 0;
  bool getline(std::string& s);
};

}  // namespace harness
