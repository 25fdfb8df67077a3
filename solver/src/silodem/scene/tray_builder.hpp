#pragma once
// Seed 001's tray as a wall of fixed balls (docs/case-format.md "walls", type "tray"): a floor along
// x with slots cut across it and a side wall at each end; one row of balls in the plane y = centre.y
// (depth 0, for the planar mode) or a box of square nets `depth` deep with a front and a back.
#include <vector>

#include "silodem/case/case_config.hpp"
#include "silodem/core/random.hpp"

namespace silodem {

/// Nominal surfaces: the floor at z = centre.z (balls below it), the side walls at x = centre.x ±
/// length/2 up to centre.z + height (balls outside), and for a box the faces y = centre.y ± depth/2.
/// The edge balls of a slot sit at x ± (width/2 + r̄), so balls of the mean radius leave exactly
/// the slot's width between them.
std::vector<BallSpec> build_tray(const WallSpec& w, Random& rng);

/// Nominal-surface points of the tray, `step` apart, for the hole search (slots and their edge
/// balls' reach left out).
std::vector<Vec3> tray_surface_samples(const WallSpec& w, double step);

}  // namespace silodem
