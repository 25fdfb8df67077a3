// Seed 001's tray as a wall of balls (scene/tray_builder.hpp): the floor and side walls on their
// nominal surfaces, each slot exactly its width between the edge balls (equal radii), no other gap
// a grain could pass, a box's slots across its whole depth; the loader refuses slots off the floor
// or narrower than a grain, a box net with holes, and a pressure map on a tray; a planar case takes a
// tray of depth 0 and vibrates it in the plane.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../case_runs.hpp"
#include "silodem/case/case_error.hpp"
#include "silodem/case/case_loader.hpp"
#include "silodem/scene/wall_builders.hpp"

using namespace silodem;
using nlohmann::json;

using silodem_test::refusal;

namespace {

constexpr double kR = 0.004;

WallSpec tray(double depth) {
  WallSpec w;
  w.name = "tray";
  w.type = "tray";
  w.material = "wall";
  w.r_min = w.r_max = kR;
  w.spacing = 0.5 * kR;
  w.centre = Vec3(0.1, 0.0, 0.02);
  w.length = 0.5;
  w.height = 0.05;
  w.depth = depth;
  w.slots = {{-0.125, 0.024}, {0.0, 0.024}, {0.125, 0.024}};  // the notes' reading: 3 d at L/4, L/2, 3L/4
  return w;
}

/// The floor balls' x (relative to the centre) in the row y = centre.y, sorted.
std::vector<double> floor_xs(const WallSpec& w, const std::vector<BallSpec>& balls) {
  std::vector<double> xs;
  for (const auto& b : balls)
    if (std::abs(b.position.z() - (w.centre.z() - kR)) < 1e-12 && std::abs(b.position.y() - w.centre.y()) < 1e-12)
      xs.push_back(b.position.x() - w.centre.x());
  std::sort(xs.begin(), xs.end());
  return xs;
}

json tray_case(const json& wall) {
  return {{"name", "tray"},
          {"materials", {{"grain", {{"density", 2500}, {"stiffness", 1e4}, {"damping", 0.0}}}}},
          {"balls", {{{"id", "g"}, {"material", "grain"}, {"radius", 0.004}, {"position", {0.0, 0.0, 0.05}}}}},
          {"walls", {wall}},
          {"time", {{"dt", 1e-5}, {"duration", 0.01}}}};
}

json tray_wall() {
  return {{"name", "tray"},    {"type", "tray"},  {"material", "grain"}, {"radius", {kR, kR}}, {"spacing", 0.5 * kR},
          {"centre", {0, 0, 0}}, {"length", 0.5}, {"height", 0.05},     {"slots", {{{"x", 0.0}, {"width", 0.024}}}}};
}


}  // namespace

TEST(Tray, ALineTrayHasItsSlotsExactlyAndNoOtherGap) {
  const WallSpec w = tray(0.0);
  const auto balls = build_wall(w, 3);
  for (const auto& b : balls) EXPECT_EQ(b.position.y(), w.centre.y());
  const std::vector<double> xs = floor_xs(w, balls);
  ASSERT_GT(xs.size(), 100u);
  EXPECT_NEAR(xs.front(), -0.5 * w.length, 1e-12);
  EXPECT_NEAR(xs.back(), 0.5 * w.length, 1e-12);
  // Between neighbours: either a step of at most the spacing, or a slot whose clear gap is its width.
  int slots = 0;
  for (std::size_t k = 1; k < xs.size(); ++k) {
    const double gap = xs[k] - xs[k - 1];
    if (gap <= w.spacing + 1e-12) continue;
    ++slots;
    const double centre = 0.5 * (xs[k] + xs[k - 1]);
    const auto slot = std::find_if(w.slots.begin(), w.slots.end(), [&](const auto& s) { return std::abs(s.x - centre) < 1e-12; });
    ASSERT_NE(slot, w.slots.end()) << "a gap at x = " << centre;
    EXPECT_NEAR(gap - 2.0 * kR, slot->width, 1e-12);
  }
  EXPECT_EQ(slots, 3);
  // Side walls outside the ends, up to the rim.
  double top = -INFINITY;
  for (const auto& b : balls)
    if (std::abs(std::abs(b.position.x() - w.centre.x()) - (0.5 * w.length + kR)) < 1e-12) top = std::max(top, b.position.z());
  EXPECT_NEAR(top, w.centre.z() + w.height, 1e-12);
  // Away from the slots only the dips between balls: √((s/2)² + r²) − r = 0.031 r at s = r/2.
  EXPECT_LT(largest_hole(w, balls), 0.035 * kR);
}

TEST(Tray, ABoxIsClosedButForSlotsAcrossItsDepth) {
  WallSpec w = tray(0.03);
  w.length = 0.15;  // a shorter box: the hole search samples every face at r/48
  w.slots = {{0.0, 0.024}};
  const auto balls = build_wall(w, 3);
  // A square net's dips: √(s²/2 + r²) − r = 0.061 r at s = r/2.
  EXPECT_LT(largest_hole(w, balls), 0.065 * kR);
  for (const auto& b : balls) {
    if (b.position.z() >= w.centre.z()) continue;  // floor balls only
    for (const auto& s : w.slots)
      EXPECT_GE(std::abs(b.position.x() - w.centre.x() - s.x), 0.5 * s.width + kR - 1e-12);
  }
  // Floor rows reach both faces; front and back walls exist.
  double y_lo = INFINITY, y_hi = -INFINITY;
  for (const auto& b : balls) y_lo = std::min(y_lo, b.position.y()), y_hi = std::max(y_hi, b.position.y());
  EXPECT_NEAR(y_lo, w.centre.y() - 0.5 * w.depth - kR, 1e-12);
  EXPECT_NEAR(y_hi, w.centre.y() + 0.5 * w.depth + kR, 1e-12);
  // The check can fail: a spacing too wide for a square net leaves holes a grain's fraction wide.
  WallSpec loose = w;
  loose.spacing = 1.9 * kR;
  EXPECT_GT(largest_hole(loose, build_wall(loose, 3)), 0.2 * kR);
}

TEST(Tray, TheLoaderTakesATrayAndRefusesWhatCannotBeBuilt) {
  EXPECT_EQ(refusal(tray_case(tray_wall())), "");
  json c = tray_case(tray_wall());
  c["walls"][0]["slots"] = {{{"x", -0.24}, {"width", 0.024}}};
  EXPECT_NE(refusal(c).find("overlaps the tray's end"), std::string::npos) << refusal(c);
  c["walls"][0]["slots"] = {{{"x", 0.24}, {"width", 0.024}}};
  EXPECT_NE(refusal(c).find("reaches past the tray's end"), std::string::npos) << refusal(c);
  c["walls"][0]["slots"] = {{{"x", 0.0}, {"width", 0.024}}, {{"x", 0.02}, {"width", 0.024}}};
  EXPECT_NE(refusal(c).find("the slot before it"), std::string::npos) << refusal(c);
  c["walls"][0]["slots"] = {{{"x", 0.0}, {"width", 0.006}}};
  EXPECT_NE(refusal(c).find("no ball can flow out"), std::string::npos) << refusal(c);
  c = tray_case(tray_wall());
  c["walls"][0]["depth"] = 0.03;
  c["walls"][0]["spacing"] = 1.5 * kR;
  EXPECT_NE(refusal(c).find("square net"), std::string::npos) << refusal(c);
  c = tray_case(tray_wall());
  c["walls"][0]["diameter"] = 0.1;
  EXPECT_NE(refusal(c).find("not a diameter"), std::string::npos) << refusal(c);
  c = tray_case(tray_wall());
  c["output"] = {{"probes", {{{"type", "wall_pressure"}, {"name", "p"}, {"wall", "tray"}}}}};
  EXPECT_NE(refusal(c).find("wall_load probe on a tray"), std::string::npos) << refusal(c);
}

TEST(Tray, APlanarCaseTakesALineTrayVibratingInThePlane) {
  json c = tray_case(tray_wall());
  c["dimension"] = 2;
  c["walls"][0]["motion"] = {{"oscillation", {{"amplitude", 0.01}, {"frequency", 9.0}, {"direction", {1, 0, 0}}}}};
  EXPECT_EQ(refusal(c), "");
  c["walls"][0]["motion"]["oscillation"]["direction"] = {0, 1, 0};
  EXPECT_NE(refusal(c).find("out of the plane"), std::string::npos) << refusal(c);
  c["walls"][0]["motion"]["oscillation"]["direction"] = {1, 0, 0};
  c["walls"][0]["depth"] = 0.02;
  EXPECT_NE(refusal(c).find("one row deep"), std::string::npos) << refusal(c);
}
