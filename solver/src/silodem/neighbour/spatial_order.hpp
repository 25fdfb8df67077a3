#pragma once
// Renumbering of the mobile balls in space, as LAMMPS's `atom_modify sort` does for its atoms. Not
// physics: it changes which ball has which index, never a position or a force.
//
// Why a sweep and not a space-filling curve: the one-thread force loop visits balls in index
// order and pushes each pair's reaction onto the higher ball, which reads it back when its turn
// comes. The data in flight is the front of the sweep: the balls between a ball and its
// highest-numbered partner. Sorting into slabs along the longest axis makes that front one slab
// across the two shorter axes, the smallest any order can make it. A Morton order was tried and
// ran 15-35 % slower at 10^5-10^6 balls in a flat box (its front is as large, its jumps longer).
// Case order is often a sweep already (a lattice built layer by layer, drops falling in turn),
// but along z: in a flat box at 10^6 balls that front is megabytes, and balls mix as a silo
// discharges.
// The order is a function of the positions only, so it is the same for any thread count.
#include <array>
#include <cstdint>
#include <vector>

#include "silodem/scene/particles.hpp"

namespace silodem {

/// The axes ordered by the extent `span` along them, longest first (ties in axis order): the
/// sweep's slab axis, then the middle one, then the shortest. The neighbour grid numbers its
/// cells in the same order, so both walk space alike.
std::array<int, 3> sweep_axes(const Vec3& span);

/// The mobile balls' indices sorted by the cube of edge `cell` they lie in, slab by slab along the
/// longest extent of the mobile balls, then along the middle one, then the shortest (ties by
/// index): order[k] is the old index of the ball that becomes ball k.
std::vector<std::uint32_t> sweep_order(const Particles& p, double cell);

}  // namespace silodem
