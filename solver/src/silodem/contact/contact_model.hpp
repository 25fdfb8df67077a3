#pragma once
// One contact through the chosen sub-models (docs/model.md §10): normal (linear | Hertz), tangential
// (none | sliding Coulomb | linear history spring | Mindlin), rolling (none | constant torque |
// elastic–plastic spring–dashpot).
// Stateless: what the pair is now and its committed spring in, forces, torques, the spring to keep
// and the energy terms out. The loop mechanics (slots, threads, history storage) live in
// forces/frictional_field.cpp.
#include <algorithm>
#include <cmath>

#include "silodem/case/case_config.hpp"
#include "silodem/contact/contact_law.hpp"
#include "silodem/contact/hertz.hpp"
#include "silodem/contact/pair_table.hpp"
#include "silodem/contact/rolling.hpp"
#include "silodem/contact/tangential.hpp"

namespace silodem::contact {

/// A touching pair (δ > 0) as the sub-models see it. n points from j to i.
struct ContactState {
  double delta, delta_rate;    // overlap and dδ/dt (> 0 approaching)
  Vec3 n;                      // unit normal, from j to i
  Vec3 v_rel;                  // v_i − v_j
  Vec3 w_i, w_j;               // angular velocities (a wall ball's is zero)
  double r_i, r_j;             // radii
  bool flat_j = false;         // j is a smooth wall (scene/surface.hpp): R* = r_i, no arm; v_rel and w_j its
                               // velocity at the contact point and its spin
  double m_eff;                // effective mass (the mobile ball's with a wall ball)
  double inertia_eff = 0.0;    // effective moment of inertia I_i I_j/(I_i + I_j) (I_i with a wall ball)
  double inertia_contact = 0.0;  // about the contact point: series of I + m r² (EPSD rolling only)
  double k_n, c_n;             // the paper's series constants (11), linear normal law
  const PairParams* pair;      // friction, shear and Hertz constants of the two materials
  Vec3 spring = Vec3::Zero();  // committed tangential spring, as last stored
  Vec3 rolling_angle = Vec3::Zero();  // committed rolling spring θ_r (EPSD), as last stored
  double dt;                   // the step: the spring grows by v_t Δt per evaluation
  double slip_arm_overlap = 0.5;  // the slip velocity's lever arms are r − this × δ (0: the radius, as LAMMPS)
  bool rolling_limit_with_dashpot = false;  // EPSD: the limit holds spring and dashpot (LAMMPS sds)
};

/// What the contact does to its two balls, and its energy terms.
struct Interaction {
  Vec3 force = Vec3::Zero();     // on i (its reaction on j)
  Vec3 torque_i = Vec3::Zero();  // about i's centre
  Vec3 torque_j = Vec3::Zero();  // about j's centre (a smooth wall: the rolling torque's reaction only)
  Vec3 spring = Vec3::Zero();    // the tangential spring to keep
  Vec3 rolling_angle = Vec3::Zero();  // the rolling spring to keep (EPSD)
  double elastic_normal = 0.0, p_dissipated = 0.0;  // normal spring energy, normal dashpot power
  double elastic_tangential = 0.0, p_friction = 0.0;  // tangential spring energy, power into friction
  double elastic_rolling = 0.0;                      // rolling spring energy (EPSD)
  bool sliding = false;
};

template <NormalModel Normal, TangentialModel Tangential, RollingModel Rolling, bool Clamp>
[[gnu::always_inline]] inline Interaction interact(const ContactState& s) {
  Interaction out;
  const PairParams& pp = *s.pair;
  const double r_star = s.flat_j ? s.r_i : effective_radius(s.r_i, s.r_j);
  PairForce normal;
  double c_n = s.c_n;  // the normal dashpot constant, for the tangential dashpot's ratio
  double k_n = s.k_n;  // the normal stiffness (Hertz: its tangent), for the EPSD rolling spring
  if constexpr (Normal == NormalModel::Linear) {
    normal = kelvin_voigt<Clamp>(s.k_n, s.c_n, s.delta, s.delta_rate);  // (4)
  } else {
    normal = hertz<Clamp>(pp.e_star, r_star, pp.hertz_zeta, s.m_eff, s.delta, s.delta_rate);
    c_n = hertz_damping(pp.e_star, r_star, pp.hertz_zeta, s.m_eff, s.delta);
    if constexpr (Rolling == RollingModel::Spring) k_n = 2.0 * pp.e_star * std::sqrt(r_star * s.delta);
  }
  out.force = normal.f * s.n;
  out.elastic_normal = normal.elastic;
  out.p_dissipated = normal.p_dissipated;
  const double f_n = normal.f;
  // Lever arms to the contact point, at the middle of the overlap (as LAMMPS `pair granular`).
  // A smooth wall has no arm: v_rel holds its velocity at the contact point already, and its
  // torque is taken about its axis by the caller (forces/surface_contacts.cpp).
  const double arm_i = s.r_i - 0.5 * s.delta, arm_j = s.flat_j ? 0.0 : s.r_j - 0.5 * s.delta;
  if constexpr (Tangential != TangentialModel::None) {
    const Vec3 v_t = slip_velocity(s.v_rel, s.w_i, s.w_j, s.r_i - s.slip_arm_overlap * s.delta,
                                   s.flat_j ? 0.0 : s.r_j - s.slip_arm_overlap * s.delta, s.n);
    TangentialForce t;
    if constexpr (Tangential == TangentialModel::CoulombSliding) {
      t = coulomb_sliding(v_t, pp.sliding_damping, pp.friction, f_n);
    } else {
      const double k_t = Tangential == TangentialModel::Mindlin ? mindlin_stiffness(pp.g_star, r_star, s.delta)
                                                                : pp.shear_ratio * s.k_n;
      t = history_spring(spring_in_tangent_plane(s.spring, s.n), v_t, s.dt, k_t, pp.shear_damping_ratio * c_n,
                         pp.friction, f_n);
    }
    out.force += t.force;
    out.spring = t.spring;
    const Vec3 lever = s.n.cross(t.force);  // torque = (contact point − centre) × force
    out.torque_i = -arm_i * lever;
    out.torque_j = -arm_j * lever;
    out.elastic_tangential = t.elastic;
    out.p_friction = -t.force.dot(v_t);
    out.sliding = t.sliding;
  }
  if constexpr (Rolling == RollingModel::ConstantTorque) {
    const RollingTorque m = constant_rolling_torque(s.w_i - s.w_j, s.n, pp.rolling_friction, r_star, f_n,
                                                    s.inertia_eff, s.dt);
    out.torque_i += m.torque;
    out.torque_j -= m.torque;
    out.p_friction += m.power;
  } else if constexpr (Rolling == RollingModel::Spring) {
    const double k_r = epsd_rolling_stiffness(k_n, pp.rolling_friction, r_star);
    const RollingSpring m = rolling_spring(spring_in_tangent_plane(s.rolling_angle, s.n), s.w_i - s.w_j, s.n, k_r,
                                           epsd_rolling_damping(pp.rolling_damping_ratio, s.inertia_contact, k_r),
                                           pp.rolling_friction, r_star, f_n, s.dt, s.rolling_limit_with_dashpot);
    out.torque_i += m.torque;
    out.torque_j -= m.torque;
    out.p_friction += m.power;
    out.rolling_angle = m.angle;
    out.elastic_rolling = m.elastic;
  }
  return out;
}

}  // namespace silodem::contact
