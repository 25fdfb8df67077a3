#pragma once
// Silo walls made of fixed, overlapping balls with random radii (1) (docs/model.md §3): the shapes of
// Algorithm 5's wall(d_h, h_h, d_c, h_c, k_w, c_w) — a vertical cylinder, a flat bottom (with an
// optional outlet hole), a conical hopper — and a gate closing an outlet. The builder runs at load
// time and turns each wall into ordinary fixed balls of the case, so every code (and every probe)
// sees exactly the same wall.
#include <string>
#include <vector>

#include "silodem/case/case_config.hpp"

namespace silodem {



/// Fixed balls of one wall. The nominal wall surface (the silo's inner surface) touches balls of
/// the mean radius; radii are drawn from `seed` so the roughness is reproducible.
std::vector<BallSpec> build_wall(const WallSpec& w, std::uint64_t seed);

/// The largest gap a wall leaves: the radius of the biggest ball whose centre can sit on the
/// nominal surface without touching any wall ball, found by sampling the surface on a fine grid
/// (outlet holes excluded). A ball larger than this cannot pass through the wall.
double largest_hole(const WallSpec& w, const std::vector<BallSpec>& balls);

}  // namespace silodem
