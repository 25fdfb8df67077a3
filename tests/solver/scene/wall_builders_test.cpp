// Wall builders: radii within the range (1), the nominal surface where asked, overlapping balls,
// tight walls (no ball of the smallest mobile radius fits through anywhere but the outlet), and
// the outlet left open.
#include <gtest/gtest.h>

#include <cmath>

#include "silodem/scene/wall_builders.hpp"

using namespace silodem;

namespace {
WallSpec spec(const std::string& type) {
  WallSpec w;
  w.name = type;
  w.type = type;
  w.material = "wall";
  w.r_min = 0.004;
  w.r_max = 0.005;
  w.spacing = 0.006;
  w.centre = Vec3(0.01, -0.02, 0.1);
  w.diameter = 0.08;
  w.height = 0.1;
  return w;
}
}  // namespace

TEST(WallBuilders, CylinderRadiiSurfaceAndTightness) {
  const WallSpec w = spec("cylinder");
  const auto balls = build_wall(w, 1);
  ASSERT_GT(balls.size(), 500u);
  for (const auto& b : balls) {
    EXPECT_TRUE(b.fixed);
    EXPECT_GE(b.radius, w.r_min);
    EXPECT_LE(b.radius, w.r_max);
    // Centres at the mean radius behind the nominal surface D/2.
    EXPECT_NEAR(std::hypot(b.position.x() - 0.01, b.position.y() + 0.02), 0.04 + 0.0045, 1e-12);
    EXPECT_GE(b.position.z(), 0.1 - 1e-12);
    EXPECT_LE(b.position.z(), 0.2 + 1e-12);
  }
  // The largest ball that can sit on the surface without touching the wall is far smaller than a
  // 4 mm grain: nothing passes.
  EXPECT_LT(largest_hole(w, balls), 0.002);
}

TEST(WallBuilders, LooseSpacingLeavesAHoleTheCheckFinds) {
  WallSpec w = spec("cylinder");
  w.spacing = 0.016;  // balls 16 mm apart with radii 4-5 mm: gaps of ~4 mm
  EXPECT_GT(largest_hole(w, build_wall(w, 1)), 0.002);
}

TEST(WallBuilders, DiskWithOutletAndCone) {
  WallSpec d = spec("disk");
  d.hole_diameter = 0.03;
  const auto disk = build_wall(d, 2);
  for (const auto& b : disk) {
    const double rho = std::hypot(b.position.x() - 0.01, b.position.y() + 0.02);
    EXPECT_GE(rho, 0.015 - 1e-12);  // the outlet stays open
    EXPECT_LE(rho, 0.04 + 1e-12);
    EXPECT_NEAR(b.position.z(), 0.1 - 0.0045, 1e-12);  // surface at centre.z, balls below it
  }
  EXPECT_LT(largest_hole(d, disk), 0.002);
  WallSpec c = spec("cone");
  c.hole_diameter = 0.03;
  const auto cone = build_wall(c, 3);
  EXPECT_LT(largest_hole(c, cone), 0.002);
  double z_min = 1e9;
  for (const auto& b : cone) z_min = std::min(z_min, b.position.z());
  EXPECT_LT(z_min, 0.0 + 0.001);  // reaches down to the outlet at centre.z − height
}

TEST(WallBuilders, SeedFixesTheRoughness) {
  const WallSpec w = spec("disk");
  const auto a = build_wall(w, 5), b = build_wall(w, 5), c = build_wall(w, 6);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a[10].radius, b[10].radius);
  EXPECT_NE(a[10].radius, c[10].radius);
}
