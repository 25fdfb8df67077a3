#pragma once
// A wall's prescribed rigid motion (a vibrating tray, a rotating mill): from start_time t0 on,
//   x(t) = c + R(θ(t)) (x0 − c) + a(t) e,   θ(t) = Ω (t − t0),
//   a(t) = A [sin(2π f (t − t0) + φ) − sin φ],
// the sum of a turn about the axis through c and a harmonic translation along e; before t0 the
// wall is at rest at x0, and it leaves x0 without a jump (φ sets the velocity it starts with). The velocity of the wall's material point at x is the rigid-body field
//   v(x, t) = ω × (x − c − a(t) e) + ȧ(t) e,   ω = Ω n,   ȧ = 2π f A cos(2π f (t − t0) + φ).
// Closed forms in t: a wall's place never drifts with the number of steps (LAMMPS fix move wiggle
// and rotate, YADE's HarmonicMotionEngine and RotationEngine move by the same laws; their phase
// conventions are translated in the harness).
#include <Eigen/Geometry>

#include <cmath>

#include "silodem/core/types.hpp"

namespace silodem {

using Mat3 = Eigen::Matrix3d;

struct MotionLaw {
  double start_time = 0.0;        // t0, s
  Vec3 direction = Vec3::UnitX();  // e, unit
  double amplitude = 0.0;          // A, m (0: no translation)
  double frequency = 0.0;          // f, Hz
  double phase = 0.0;              // φ, rad
  Vec3 centre = Vec3::Zero();      // c, a point of the rotation axis, m
  Vec3 axis = Vec3::UnitZ();       // n, unit; Ω > 0 turns counter-clockwise about it
  double angular_speed = 0.0;      // Ω, rad/s (0: no rotation)
};

/// Where the law has taken the wall at time t: its turn, its shift and their rates.
struct Pose {
  Mat3 rotation = Mat3::Identity();  // R(θ(t))
  Vec3 shift = Vec3::Zero();         // a(t) e
  Vec3 shift_rate = Vec3::Zero();    // ȧ(t) e
  Vec3 omega = Vec3::Zero();         // ω, rad/s (zero before t0)
};

inline Pose pose_at(const MotionLaw& m, double t) {
  Pose q;
  const double s = t - m.start_time;
  if (s < 0.0) return q;
  if (m.angular_speed != 0.0) {
    q.rotation = Eigen::AngleAxisd(m.angular_speed * s, m.axis).toRotationMatrix();
    q.omega = m.angular_speed * m.axis;
  }
  if (m.amplitude != 0.0) {
    const double w = 2.0 * kPi * m.frequency, arg = w * s + m.phase;
    q.shift = m.amplitude * (std::sin(arg) - std::sin(m.phase)) * m.direction;
    q.shift_rate = m.amplitude * w * std::cos(arg) * m.direction;
  }
  return q;
}

/// The place at pose q of the wall point that was at x0.
inline Vec3 moved_position(const MotionLaw& m, const Pose& q, const Vec3& x0) {
  return m.centre + q.rotation * (x0 - m.centre) + q.shift;
}

/// The velocity of the wall's material point now at x.
inline Vec3 wall_velocity(const MotionLaw& m, const Pose& q, const Vec3& x) {
  return q.omega.cross(x - m.centre - q.shift) + q.shift_rate;
}

}  // namespace silodem
