#pragma once
// Tangential contact sub-models (docs/model.md §10): stateless functions of one contact's slip
// velocity, its committed spring and its normal force. The force loop (forces/frictional_field.cpp)
// keeps the spring per contact, rotates nothing itself and books the energy terms returned here.
// Sign convention as in contact_law.hpp: n points from j to i; the force returned acts on i at the
// contact point, its reaction on j.
#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>  // cross products

#include "silodem/core/types.hpp"

namespace silodem::contact {

/// Velocity of i's surface relative to j's at the contact point (docs/model.md §10.1):
/// v_c = (v_i − v_j) − (a_i ω_i + a_j ω_j) × n, with the lever arms a = r − δ/2 from each centre to
/// the contact point. Its tangential part is the slip velocity v_t = v_c − (v_c·n) n.
[[gnu::always_inline]] inline Vec3 slip_velocity(const Vec3& v_rel, const Vec3& w_i, const Vec3& w_j, double arm_i, double arm_j,
                          const Vec3& n) {
  const Vec3 v_c = v_rel - (arm_i * w_i + arm_j * w_j).cross(n);
  return v_c - v_c.dot(n) * n;
}

/// What a tangential law gives one contact.
struct TangentialForce {
  Vec3 force = Vec3::Zero();   // on i at the contact point, N
  Vec3 spring = Vec3::Zero();  // the spring displacement ξ to keep for the next step, m
  double elastic = 0.0;        // ½ k_t |ξ|², J
  bool sliding = false;        // the Coulomb cap |F_t| = μ F_n was reached
};

/// Sliding Coulomb friction without stick, the law of seeds 001 and 003 in vector form:
/// F_t = −min(μ F_n, γ_t |v_t|) v_t/|v_t|. No spring: nothing is stored, all work is dissipated.
[[gnu::always_inline]] inline TangentialForce coulomb_sliding(const Vec3& v_t, double gamma_t, double mu, double f_n) {
  TangentialForce out;
  const double speed = v_t.norm();
  if (!(speed > 0.0)) return out;
  const double cap = mu * std::max(f_n, 0.0), viscous = gamma_t * speed;
  out.sliding = viscous >= cap;
  out.force = -(std::min(cap, viscous) / speed) * v_t;
  return out;
}

/// The committed spring carried into the current tangent plane: its normal part removed and its
/// length kept, so a rotating contact neither stores nor loses spring energy by turning (Luding
/// 2008, eq. 17; LAMMPS `pair granular` rotates the same way). docs/model.md §10.2.
[[gnu::always_inline]] inline Vec3 spring_in_tangent_plane(const Vec3& spring, const Vec3& n) {
  const double length2 = spring.squaredNorm();
  if (!(length2 > 0.0)) return Vec3::Zero();
  const Vec3 in_plane = spring - spring.dot(n) * n;
  const double in_plane2 = in_plane.squaredNorm();
  if (!(in_plane2 > 0.0)) return Vec3::Zero();
  return in_plane * std::sqrt(length2 / in_plane2);
}

/// Linear spring with history, capped by Coulomb (Cundall & Strack 1979): ξ ← ξ + v_t Δt,
/// F_t = −k_t ξ − γ_t v_t, and when |F_t| > μ F_n the force is scaled to the cap and the spring
/// is reset to what the capped force holds, ξ = −(F_t + γ_t v_t)/k_t (as LAMMPS does), so that a
/// contact that stops sliding sticks at once. `spring` is the committed ξ already in the tangent
/// plane (spring_in_tangent_plane). Mindlin no-slip is this law with k_t = 8 G* √(R* δ).
[[gnu::always_inline]] inline TangentialForce history_spring(const Vec3& spring, const Vec3& v_t, double dt, double k_t, double gamma_t,
                                      double mu, double f_n) {
  TangentialForce out;
  out.spring = spring + dt * v_t;
  Vec3 force = -k_t * out.spring - gamma_t * v_t;
  const double cap = mu * std::max(f_n, 0.0);
  const double magnitude2 = force.squaredNorm();
  if (magnitude2 > cap * cap) {
    out.sliding = true;
    force *= magnitude2 > 0.0 ? cap / std::sqrt(magnitude2) : 0.0;
    out.spring = k_t > 0.0 ? Vec3(-(force + gamma_t * v_t) / k_t) : Vec3::Zero();
  }
  out.force = force;
  out.elastic = 0.5 * k_t * out.spring.squaredNorm();
  return out;
}

/// Mindlin's no-slip tangential stiffness for a Hertz contact, k_t = 8 G* √(R* δ) (Mindlin 1949;
/// Chung & Ooi 2011, eq. for their tests 4–8).
[[gnu::always_inline]] inline double mindlin_stiffness(double g_star, double r_star, double delta) {
  return 8.0 * g_star * std::sqrt(r_star * std::max(delta, 0.0));
}

}  // namespace silodem::contact
