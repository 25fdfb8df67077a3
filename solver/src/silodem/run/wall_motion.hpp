#pragma once
// Walls that move at a prescribed velocity (a `move_wall` stage event: a piston, a shear box). A wall
// ball's velocity is given, not integrated: each step it is advanced by v Δt, and the contact laws
// read that velocity as they read a grain's. Its work on the grains is energy brought in.
#include "silodem/scene/particles.hpp"

namespace silodem {

/// Advances every wall ball that has a velocity by one step, x += v Δt. Returns the walls' power
/// on the grains before the move (wall_power).
double move_walls(Particles& p, double dt);

/// The walls' power on the grains, −Σ f_w·v_w over wall balls (f_w: the contact force on wall ball w).
double wall_power(const Particles& p);

}  // namespace silodem
