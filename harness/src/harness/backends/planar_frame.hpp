#pragma once
// The planar mode in LAMMPS and LIGGGHTS. Their 2-D mode keeps atoms in the x-y plane (`dimension 2`,
// z periodic, `fix enforce2d`); silodem's keeps them in x-z with gravity along -z. The quarter turn
// about x, (x, y, z) -> (x, z, -y), takes silodem's plane onto theirs: gravity -z becomes -y, and a
// disc's spin about y becomes a spin about -z. It is a proper rotation, so spins and torques turn as
// positions do. The deck is written in the turned frame and the dump turned back when it is read
// (Translation::frame), so nothing after the backend sees the swap.
#include <string>

#include "harness/backends/translation.hpp"

namespace harness {

/// The turn from silodem's axes to a LAMMPS-family 2-D run's: x_code = Q x_silodem.
silodem::Mat3 planar_turn();

/// The translation with every position, velocity, spin, event and wall law in the frame q
/// (Translation::frame records it for the dump's way back).
Translation in_frame(Translation tr, const silodem::Mat3& q);

/// The grain inertias I/(m r^2) a LAMMPS-family code integrates in 2-D.
struct PlanarInertias {
  bool sphere = false;  // 2/5: LAMMPS's fix nve/sphere
  bool disc = false;    // 1/2: LAMMPS's fix nve/sphere disc; LIGGGHTS's fix nve/sphere in 2-D (its only one)
};

/// What the planar mode cannot carry in a LAMMPS-family code ("" if nothing): smooth surfaces and
/// closures (their regions are not turned), and a grain inertia the code's integrator does not have.
std::string planar_limits(const silodem::CaseConfig& cfg, const Translation& tr, const std::string& code,
                          PlanarInertias has);

/// The box boundary line ("boundary m m m", or "m m p" for a 2-D run: z must be periodic there).
std::string lammps_family_boundary(const silodem::CaseConfig& cfg);

}  // namespace harness
