#pragma once
// The planar mode ("dimension": 2; docs/model.md §13): the grains' centres move in the x–z plane
// (y = 0) and they spin about y only. A case may use it only if nothing it sets moves a grain out of
// that plane; these checks name the first thing that would.
#include "silodem/case/case_config.hpp"

namespace silodem {

/// Throws CaseError naming the ball, wall, surface, drop inlet, event or gravity that leaves the
/// plane y = 0 of a planar case (a no-op for a 3-D one).
void check_planar(const CaseConfig& cfg);

}  // namespace silodem
