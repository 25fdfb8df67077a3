#pragma once
// Seed 003's mill as a wall of fixed balls (docs/case-format.md "walls", type "drum"): a regular
// polygon of `sides` edges about an axis along y through `centre`, circumscribed by diameter/2, with
// optional lifters (radial bars of balls standing `lifter_height` in from the wall), one ring in the
// plane y = centre.y (length 0, for the planar mode) or a prism `length` long closed by end plates.
#include <vector>

#include "silodem/case/case_config.hpp"
#include "silodem/core/random.hpp"

namespace silodem {

/// Nominal surfaces: the polygon's inner faces (balls outside them), the lifters' centre lines, and
/// for a prism the end plates y = centre.y ± length/2 (balls outside).
std::vector<BallSpec> build_drum(const WallSpec& w, Random& rng);

/// Nominal-surface points of the drum's faces and end plates, `step` apart (lifters left out: they
/// stand inside the charge), for the hole search.
std::vector<Vec3> drum_surface_samples(const WallSpec& w, double step);

}  // namespace silodem
