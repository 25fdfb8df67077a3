#pragma once
// Walls that move (docs/model.md §12): a wall that follows a motion law (motion/motion_law.hpp: a
// vibrating tray, a rotating drum), and a wall or listed fixed ball set moving at a constant
// velocity by a `move_wall` stage event (a piston, a shear box). A wall ball's place and velocity
// are given, not integrated: each step every moving wall ball goes to its place at the step's end
// before the step's force evaluation, and the contact laws read its velocity (and, in a rotating
// scene, its angular velocity: the wall's ω) as they read a grain's. Its work on the grains is
// energy brought in.
#include <cstdint>
#include <string>
#include <vector>

#include "silodem/case/case_config.hpp"
#include "silodem/motion/motion_law.hpp"
#include "silodem/scene/particles.hpp"

namespace silodem {

class WallMotion {
 public:
  /// The walls of the case that follow a law, their balls found by id in p, each at its place at
  /// the law's origin: the case's wall balls, or cfg.wall_reference in a continuation. Marks p's
  /// walls as driven (Particles::driven_walls) when there is one.
  WallMotion(const CaseConfig& cfg, Particles& p);

  /// Puts the law walls' balls at their places and velocities at time t (a run's start).
  void place(Particles& p, double t);
  /// One step: law walls to their places at t_next, walls of constant velocity on by v dt.
  /// Returns the walls' power on the grains before the move (wall_power).
  double advance(Particles& p, double t_next, double dt);

  /// The law of the wall with this name, or nullptr.
  const MotionLaw* law(const std::string& wall) const;
  /// The place at the law's origin of wall ball i, if it belongs to a law wall (else its place now).
  Vec3 reference_position(const Particles& p, std::size_t i);

 private:
  struct Driven {
    std::string wall;
    MotionLaw law;
    std::vector<std::string> ids;  // its balls' ids, and their places at the origin
    std::vector<Vec3> x0;
    std::vector<std::size_t> index;  // where each is in p now; kNone once it is no wall ball
  };
  static constexpr std::size_t kNone = ~std::size_t(0);
  void locate(const Particles& p);  // after a change of indices (Particles::topology)
  std::vector<Driven> driven_;
  std::vector<std::int32_t> owner_;  // per ball of p: the Driven it belongs to, or -1
  std::vector<std::uint32_t> slot_;  // its slot in that Driven
  std::uint64_t topology_ = ~std::uint64_t(0);
};

/// The walls' power on the grains, −Σ (f_w·v_w + t_w·ω_w) over wall balls (f_w, t_w: the contact
/// force and torque on wall ball w; the torque term in a rotating scene).
double wall_power(const Particles& p);

}  // namespace silodem
