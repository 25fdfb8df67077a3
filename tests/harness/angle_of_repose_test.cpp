// The angle of repose of a heap whose surface is known: a cone of grains of slope 27° (the top of
// each radial bin's highest grain on the cone, grains below it inside) gives back 27°; a grain that
// rolled far out and the fixed base balls under the heap do not move it; a bare floor gives no angle.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "harness/angle_of_repose.hpp"

namespace {

constexpr double kR = 0.0045, kBin = 0.01, kHeight = 0.08, kAxisX = 0.02, kAxisY = -0.01;

silodem::BallSpec grain(double r, double angle, double top) {
  silodem::BallSpec b;
  b.radius = kR;
  b.position = silodem::Vec3(kAxisX + r * std::cos(angle), kAxisY + r * std::sin(angle), top - kR);
  return b;
}

/// A cone of slope `deg` standing on z = 0, grains on its surface at every bin's centre and below.
std::vector<silodem::BallSpec> cone(double deg) {
  std::vector<silodem::BallSpec> balls;
  const double t = std::tan(deg * std::numbers::pi / 180.0);
  for (int k = 0; (k + 0.5) * kBin * t < kHeight; ++k) {
    const double r = (k + 0.5) * kBin, top = kHeight - r * t;
    for (double a = 0.0; a < 6.0; a += 1.0) {
      balls.push_back(grain(r, a, top));
      if (top > 4 * kR) balls.push_back(grain(r, a + 0.5, top - 2 * kR));  // one below, inside the heap
    }
  }
  balls.push_back(grain(0.0, 0.0, 2 * kR));  // the heap's foot: a grain resting on z = 0 at the axis
  return balls;
}

}  // namespace

TEST(AngleOfRepose, AConeOfKnownSlopeGivesItsAngleBack) {
  for (const double deg : {22.0, 27.0, 35.0}) {
    auto balls = cone(deg);
    silodem::BallSpec stray = grain(0.3, 1.0, 2 * kR);  // rolled far out: beyond the slope, at the foot's height
    balls.push_back(stray);
    silodem::BallSpec base = grain(0.05, 2.0, -0.001);  // a fixed ball of the base, under the heap's foot
    base.fixed = true;
    balls.push_back(base);
    const auto p = harness::heap_profile(balls, kAxisX, kAxisY, kBin);
    const auto f = harness::heap_slope(p, 0.25, 0.75);
    EXPECT_NEAR(f.angle_deg, deg, 1e-9) << deg;
    EXPECT_NEAR(f.r2, 1.0, 1e-12);
    EXPECT_GE(f.bins, 3);
  }
}

TEST(AngleOfRepose, AHeapWithARoundedTopAndFootIsFittedOnItsSlopeOnly) {
  // Top and foot flattened (above 0.8 and below 0.2 of the height): the fit between 0.25 and 0.75 sees the cone.
  auto balls = cone(30.0);
  for (auto& b : balls) {
    const double top = b.position.z() + kR;
    b.position.z() = std::clamp(top, 0.2 * kHeight, 0.8 * kHeight) - kR;
  }
  const auto f = harness::heap_slope(harness::heap_profile(balls, kAxisX, kAxisY, kBin), 0.25, 0.75);
  // The foot grain at the axis is lifted too, so heights count from 0.2 H: the band is 0.25-0.75 of 0.6 H
  // above it, still on the cone's straight part.
  EXPECT_NEAR(f.angle_deg, 30.0, 1e-9);
}

TEST(AngleOfRepose, ALayerOneGrainDeepHasNoSlopeToMeasure) {
  std::vector<silodem::BallSpec> layer;
  for (int k = 0; k < 20; ++k) layer.push_back(grain(k * kBin, 0.0, 2 * kR));
  const auto f = harness::heap_slope(harness::heap_profile(layer, kAxisX, kAxisY, kBin), 0.25, 0.75);
  EXPECT_TRUE(std::isnan(f.angle_deg));
}
