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
[[gnu::always_inline]] inline RollingTorque constant_rolling_torque(const Vec3& w_rel, const Vec3& n, double mu_r, double r_star, double f_n,
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

/// What the rolling spring gives one contact.
struct RollingSpring {
  Vec3 torque = Vec3::Zero();  // on i (−torque on j), N m
  Vec3 angle = Vec3::Zero();   // the spring's relative rolling angle θ_r to keep, rad
  double elastic = 0.0;        // ½ k_r |θ_r|², J
  double power = 0.0;          // taken from the balls' rotation by spring and dashpot, W
  bool plastic = false;        // the limit torque M_m = μ_r R* F_n was reached
};

/// Elastic–plastic spring–dashpot rolling resistance (Iwashita & Oda 1998; model C of Ai, Chen,
/// Rotter & Ooi 2011; LIGGGHTS `rolling_friction epsd`): θ_r ← θ_r + ω_r Δt with ω_r the rolling part of
/// ω_i − ω_j, spring torque M_k = −k_r θ_r held to |M_k| ≤ M_m = μ_r R* F_n (past it the spring
/// is reset to what the limit holds, θ_r = −M_k/k_r, as the tangential spring is), and a dashpot
/// M_d = −C_r ω_r only while the spring is below the limit (Ai's f = 0 at full mobilisation).
/// With `limit_with_dashpot` the limit holds M_k + M_d instead and the spring is reset to what the
/// held total leaves after the dashpot, θ_r = −(M − M_d)/k_r (LAMMPS 29Sep2021 `rolling sds`).
/// `angle` is the committed θ_r already in the tangent plane (spring_in_tangent_plane).
[[gnu::always_inline]] inline RollingSpring rolling_spring(const Vec3& angle, const Vec3& w_rel, const Vec3& n, double k_r, double c_r,
                                    double mu_r, double r_star, double f_n, double dt,
                                    bool limit_with_dashpot = false) {
  RollingSpring out;
  const Vec3 w_roll = w_rel - w_rel.dot(n) * n;
  out.angle = angle + dt * w_roll;
  const Vec3 damper = -c_r * w_roll;
  Vec3 held = limit_with_dashpot ? Vec3(-k_r * out.angle + damper) : Vec3(-k_r * out.angle);
  const double limit = mu_r * r_star * std::max(f_n, 0.0), size2 = held.squaredNorm();
  if (size2 > limit * limit) {
    out.plastic = true;
    held *= limit / std::sqrt(size2);
    const Vec3 spring = limit_with_dashpot ? Vec3(held - damper) : held;
    out.angle = k_r > 0.0 ? Vec3(-spring / k_r) : Vec3::Zero();
  }
  out.torque = out.plastic || limit_with_dashpot ? held : Vec3(held + damper);
  out.elastic = 0.5 * k_r * out.angle.squaredNorm();
  out.power = -out.torque.dot(w_roll);
  return out;
}

/// Rolling stiffness of the EPSD model, k_r = 2.25 k_n μ_r² R*² (Ai et al. 2011, whose prefactor
/// 2.25 holds in 3-D; LIGGGHTS `epsd` takes the same): with k_n the normal contact stiffness (Hertz: its tangent
/// 2E*√(R*δ)).
[[gnu::always_inline]] inline double epsd_rolling_stiffness(double k_n, double mu_r, double r_star) {
  return 2.25 * k_n * mu_r * mu_r * r_star * r_star;
}

/// The rolling dashpot C_r = 2 η_r √(I_r k_r) with I_r the pair's moment of inertia about the
/// contact point, 1/I_r = 1/(I_i + m_i r_i²) + 1/(I_j + m_j r_j²) (Ai et al. 2011); a wall
/// ball adds nothing (1/∞).
[[gnu::always_inline]] inline double epsd_rolling_damping(double eta_r, double inertia_contact, double k_r) {
  return 2.0 * eta_r * std::sqrt(std::max(inertia_contact * k_r, 0.0));
}

}  // namespace silodem::contact
