// Algorithm 2: the first-contact root (15) (corrected sign), candidate choice, rejections, and the
// drop feeder's initial conditions (16).
#include <gtest/gtest.h>

#include <cmath>

#include "silodem/fill/drop_feeder.hpp"
#include "silodem/fill/free_fall.hpp"

using namespace silodem;

namespace {
Particles fixed_balls(std::initializer_list<std::pair<Vec3, double>> balls) {
  Particles p;
  int n = 0;
  for (const auto& [x, r] : balls) {
    std::string id = std::to_string(n++);  // not "w" + to_string(): GCC 12 -Wrestrict false positive
    p.add({x, Vec3::Zero(), r, 1.0, 1e5, 1.0, 0, id}, true);
  }
  return p;
}
}  // namespace

TEST(FirstContactHeight, MatchesSphereGeometry) {
  // Touch when b² + z² = R² (docs/theory.md §3a): z = √(R² − b²) above the obstacle's centre.
  const Vec3 start(0.003, 0.004, 1.0);  // b = 0.005 from the obstacle axis
  const auto h = first_contact_height(start, 0.006, Vec3(0, 0, 0.2), 0.007);
  ASSERT_TRUE(h);
  EXPECT_NEAR(1.0 - *h - 0.2, std::sqrt(0.013 * 0.013 - 0.005 * 0.005), 1e-14);
}

TEST(FirstContactHeight, GrazeAndMissAreNoContact) {
  EXPECT_FALSE(first_contact_height(Vec3(0.01, 0, 1), 0.005, Vec3::Zero(), 0.005));  // D = 0: graze
  EXPECT_FALSE(first_contact_height(Vec3(0.02, 0, 1), 0.005, Vec3::Zero(), 0.005));  // D < 0
}

TEST(FindFirstContact, HighestObstacleWinsNotTheNearestAxis) {
  // The lower ball lies right under the drop, the upper one off-axis: the upper is hit first.
  Particles p = fixed_balls({{Vec3(0, 0, 0), 0.005}, {Vec3(0.007, 0, 0.02), 0.005}});
  const FirstContact fc = find_first_contact(p, Vec3(0, 0, 0.1), 0.005);
  ASSERT_EQ(fc.kind, FirstContact::Kind::Contact);
  EXPECT_EQ(fc.obstacle, 1u);
  EXPECT_NEAR(fc.h, 0.1 - 0.02 - std::sqrt(1e-4 - 0.007 * 0.007), 1e-15);
}

TEST(FindFirstContact, NoObstacleAndOverlappingStart) {
  Particles p = fixed_balls({{Vec3(0, 0, 0), 0.005}});
  EXPECT_EQ(find_first_contact(p, Vec3(0.5, 0, 0.1), 0.005).kind, FirstContact::Kind::NoObstacle);
  EXPECT_EQ(find_first_contact(p, Vec3(0.002, 0, 0.003), 0.005).kind, FirstContact::Kind::StartOverlaps);
  // A ball entirely above the start is no obstacle.
  Particles q = fixed_balls({{Vec3(0, 0, 1.0), 0.005}, {Vec3(0, 0, 0), 0.005}});
  const FirstContact fc = find_first_contact(q, Vec3(0, 0, 0.5), 0.005);
  ASSERT_EQ(fc.kind, FirstContact::Kind::Contact);
  EXPECT_EQ(fc.obstacle, 1u);
}

TEST(FindFirstContact, ABallInFreeFlightAheadIsNoObstacle) {
  // A mobile ball 0.2 m under the release point, right on the axis, above a fixed floor ball.
  const double g = 9.81, z0 = 0.5, zj = 0.3;
  Particles p = fixed_balls({{Vec3(0, 0, 0), 0.005}});
  p.add({Vec3(0, 0, zj), Vec3::Zero(), 0.005, 1.0, 1.0, 0.0, 0, "flying", 9}, false);
  const std::size_t j = std::size_t(p.find("flying"));
  // At rest it is the obstacle (Algorithm 2 as printed) ...
  EXPECT_EQ(find_first_contact(p, Vec3(0, 0, z0), 0.005, g).obstacle, j);
  // ... and so it is while slower than a new ball would be at its height ...
  const double v_drop = std::sqrt(2.0 * g * (z0 - zj));
  p.v[j] = Vec3(0, 0, -0.9 * v_drop);
  EXPECT_EQ(find_first_contact(p, Vec3(0, 0, z0), 0.005, g).obstacle, j);
  // ... but falling at that speed (a drop placed earlier, still in flight) a ball released now
  // never catches it: the floor ball is the first contact. Without g the printed algorithm holds.
  p.v[j] = Vec3(0, 0, -v_drop);
  const FirstContact fc = find_first_contact(p, Vec3(0, 0, z0), 0.005, g);
  ASSERT_EQ(fc.kind, FirstContact::Kind::Contact);
  EXPECT_NE(fc.obstacle, j);
  EXPECT_NEAR(fc.h, z0 - 0.01, 1e-12);
  EXPECT_EQ(find_first_contact(p, Vec3(0, 0, z0), 0.005).obstacle, j);
}

TEST(DropFeeder, PlacesAtContactWithFreeFallSpeedOrAtRest) {
  for (bool free_fall : {true, false}) {
    Particles p = fixed_balls({{Vec3(0, 0, 0), 0.005}});
    DropSpec d;
    d.material = "m";
    d.r_min = d.r_max = 0.004;
    d.z0 = 0.1;
    d.count = 1;
    d.positions = {{0.0, 0.0}};
    d.free_fall_velocity = free_fall;
    Material m{"m", 1000.0, 1e5, 1.0, ""};
    DropFeeder feeder(d, m, 0, Vec3(0, 0, -9.81), 1, 100);
    const auto rec = feeder.maybe_drop(p, 0, 0.0);
    ASSERT_TRUE(rec);
    EXPECT_EQ(rec->outcome, "placed");
    const double h = 0.1 - 0.009;
    EXPECT_NEAR(rec->h, h, 1e-15);
    ASSERT_EQ(p.n_mobile, 1u);
    EXPECT_NEAR(p.x[0].z(), 0.009, 1e-15);
    EXPECT_NEAR(p.v[0].z(), free_fall ? -std::sqrt(2 * 9.81 * h) : 0.0, 1e-12);  // (16)
    EXPECT_NEAR(p.m[0], 1000.0 * 4.0 / 3.0 * M_PI * std::pow(0.004, 3), 1e-15);  // 4/3, not 1/3
    EXPECT_TRUE(feeder.done());
  }
}

TEST(DropFeeder, WaitsWhileTheFillReachesTheReleaseHeightAndRejectsMisses) {
  Particles p = fixed_balls({{Vec3(0, 0, 0), 0.005}});
  DropSpec d;
  d.r_min = 0.004;
  d.r_max = 0.005;
  d.z0 = 0.1;
  d.count = 3;
  d.positions = {{0.3, 0.0}, {0.0, 0.0}, {0.0, 0.0}};
  Material m{"m", 1000.0, 1e5, 1.0, ""};
  DropFeeder feeder(d, m, 0, Vec3(0, 0, -9.81), 1, 100);
  EXPECT_EQ(feeder.maybe_drop(p, 0, 0.0)->outcome, "no_obstacle");  // misses everything: rejected
  EXPECT_EQ(feeder.maybe_drop(p, 1, 0.0)->outcome, "placed");
  p.x[0].z() = 0.1;  // the fill has reached z0
  EXPECT_FALSE(feeder.maybe_drop(p, 2, 0.0));
  EXPECT_EQ(feeder.rejected(), 1);
  EXPECT_EQ(feeder.placed(), 1);
}

TEST(DropFeeder, FullWhenTheMedianColumnTopReachesTheLevelNotWhenOneTowerDoes) {
  // Inlet 4 cm square, r_max 2.5 mm: 4 × 4 columns of 1 cm.
  Particles p = fixed_balls({{Vec3(0, 0, -0.1), 0.005}});
  DropSpec d;
  d.r_min = d.r_max = 0.0025;
  d.z0 = 0.3;
  d.count = 1000;
  d.x_min = d.y_min = -0.02;
  d.x_max = d.y_max = 0.02;
  d.full_level = 0.05;
  Material m{"m", 1000.0, 1e5, 1.0, ""};
  int n = 0;
  const auto mobile = [&](double x, double y, double z) {
    p.add({Vec3(x, y, z), Vec3::Zero(), 0.0025, 1e-4, 1e5, 1.0, 0, "b" + std::to_string(n++)}, false);
  };
  for (int ix = 0; ix < 4; ++ix)
    for (int iy = 0; iy < 4; ++iy) mobile(-0.015 + 0.01 * ix, -0.015 + 0.01 * iy, 0.01);  // a flat bed
  mobile(0.0051, 0.0051, 0.2);  // one tower, far above the level
  DropFeeder feeder(d, m, 0, Vec3(0, 0, -9.81), 1, 100);
  EXPECT_NEAR(feeder.surface_height(p), 0.01, 1e-15);
  EXPECT_TRUE(feeder.maybe_drop(p, 0, 0.0));  // not full: a drop is made
  EXPECT_FALSE(feeder.full());
  for (std::size_t i = 0; i < 8; ++i) p.x[i].z() = 0.06;  // half the columns (and the tower's) reach the level
  EXPECT_GE(feeder.surface_height(p), 0.05);
  EXPECT_FALSE(feeder.maybe_drop(p, 1, 0.25));
  EXPECT_TRUE(feeder.full());
  EXPECT_TRUE(feeder.done());
  EXPECT_DOUBLE_EQ(feeder.full_time(), 0.25);
  EXPECT_FALSE(feeder.maybe_drop(p, 2, 0.5));  // the fill has ended for good
}
