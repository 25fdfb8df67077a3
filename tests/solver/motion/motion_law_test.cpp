// The motion law's closed forms against each other: the wall velocity is the time derivative of
// the place (central differences, error O(h²)), a turn of 2π brings every point back, and the
// wall leaves x0 without a jump at its start time.
#include <gtest/gtest.h>

#include <cmath>

#include "silodem/motion/motion_law.hpp"

using silodem::MotionLaw;
using silodem::Vec3;

namespace {
MotionLaw both() {
  MotionLaw m;
  m.start_time = 0.1;
  m.direction = Vec3(1, 2, 0.5).normalized();
  m.amplitude = 0.01;
  m.frequency = 9.0;
  m.phase = 0.7;
  m.centre = Vec3(0.2, -0.1, 0.05);
  m.axis = Vec3(0.3, -1, 2).normalized();
  m.angular_speed = 2.5;
  return m;
}
}  // namespace

TEST(MotionLaw, TheVelocityIsTheDerivativeOfThePlace) {
  const MotionLaw m = both();
  const Vec3 x0(0.05, 0.3, -0.2);
  const double h = 1e-5;
  for (const double t : {0.13, 0.4, 1.7}) {
    const Vec3 x = moved_position(m, pose_at(m, t), x0);
    const Vec3 dx = (moved_position(m, pose_at(m, t + h), x0) - moved_position(m, pose_at(m, t - h), x0)) / (2 * h);
    // The error of the central difference is h²/6 |x'''| ≤ h² (Ω³ ρ + (2πf)³ A) ≈ 2e-7 m/s here.
    EXPECT_LT((wall_velocity(m, pose_at(m, t), x) - dx).norm(), 1e-6) << "t = " << t;
  }
}

TEST(MotionLaw, AFullTurnBringsAPointBackAndTheStartIsContinuous) {
  MotionLaw m = both();
  m.amplitude = 0.0;
  const Vec3 x0(0.05, 0.3, -0.2);
  const double turn = 2 * M_PI / m.angular_speed;
  EXPECT_LT((moved_position(m, pose_at(m, m.start_time + turn), x0) - x0).norm(), 1e-14);
  EXPECT_GT((moved_position(m, pose_at(m, m.start_time + 0.5 * turn), x0) - x0).norm(), 0.1);
  const MotionLaw w = both();
  EXPECT_LT((moved_position(w, pose_at(w, 0.05), x0) - x0).norm(), 1e-16);  // at rest before the start
  EXPECT_LT((moved_position(w, pose_at(w, w.start_time + 1e-9), x0) - x0).norm(), 1e-9);
  EXPECT_TRUE(pose_at(w, 0.05).omega.isZero());
}
