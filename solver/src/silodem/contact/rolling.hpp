#pragma once
// Rolling resistance sub-models (docs/model.md §10.5): stateless functions of the pair's relative
// angular velocity and normal force. n points from j to i, as in contact_law.hpp.
#include <algorithm>
#include <cmath>

#include "silodem/core/types.hpp"

namespace silodem::contact {

struct RollingTorque {
  Vec3 torque = Vec3::Zero();  // on i (−torque on j), N m
  double power = 0.0;          // taken from the balls' rotation, W (≥ 0)
};

/// Constant directional torque (Zhou et al. 1999, model A of Ai et al. 2011): M = −μ_r R* F_n ω̂_r
/// against the rolling part ω_r of ω_i − ω_j (its twist about n removed). A constant torque
/// would reverse a rolling ball that it has just stopped and then chatter about ω = 0; its size is
/// therefore held to what stops the relative rolling within one step, I* |ω_r| / Δt, so a rolling
/// ball comes to rest and stays there. The torque takes energy only: M·ω_r ≤ 0.
inline RollingTorque constant_rolling_torque(const Vec3& w_rel, const Vec3& n, double mu_r, double r_star, double f_n,
                                             double inertia_eff, double dt) {
  RollingTorque out;
  const Vec3 w_roll = w_rel - w_rel.dot(n) * n;
  const double rate = w_roll.norm();
  if (!(rate > 0.0)) return out;
  const double magnitude = std::min(mu_r * r_star * std::max(f_n, 0.0), inertia_eff * rate / dt);
  out.torque = -(magnitude / rate) * w_roll;
  out.power = magnitude * rate;
  return out;
}

}  // namespace silodem::contact
