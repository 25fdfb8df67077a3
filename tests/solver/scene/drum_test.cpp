// Seed 003's mill as a wall of balls (scene/drum_builder.hpp): every face ball sits r̄ behind its
// face of the polygon, lifters stand on face middles, the ring and a prism's end plates leave no gap
// a grain could pass; the loader refuses lifters off the face middles or reaching the axis; a planar
// mill (a ring turning about y) keeps its charge inside and closes its energy ledger with the wall's work.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "../case_runs.hpp"
#include "silodem/scene/wall_builders.hpp"

using namespace silodem;
using nlohmann::json;
using silodem_test::refusal;

namespace {

constexpr double kR = 0.02, kSpacing = 0.02;

WallSpec drum(double length) {
  WallSpec w;
  w.name = "mill";
  w.type = "drum";
  w.material = "steel";
  w.r_min = w.r_max = kR;
  w.spacing = kSpacing;
  w.centre = Vec3(0.0, 0.0, 1.2);
  w.diameter = 2.0;
  w.sides = 24;
  w.length = length;
  w.lifters = 4;
  w.lifter_height = 0.1;
  return w;
}

json mill_wall() {
  return {{"name", "mill"},           {"type", "drum"},    {"material", "steel"}, {"radius", {kR, kR}},
          {"spacing", kSpacing},      {"centre", {0, 0, 0}}, {"diameter", 2.0},   {"sides", 24},
          {"lifters", {{"count", 4}, {"height", 0.1}}}};
}

json mill_case(const json& wall) {
  json balls = json::array();
  for (int k = 0; k < 20; ++k)  // a loose charge in the lower half, in the plane
    balls.push_back({{"id", "b" + std::to_string(k)}, {"material", "steel"}, {"radius", 0.05},
                     {"position", {-0.5 + 0.11 * (k % 10), 0.0, -0.55 - 0.11 * (k / 10)}}});
  return {{"name", "mill"},
          {"dimension", 2},
          {"contact", {{"tangential", "linear_history"}}},
          {"materials", {{"steel", {{"density", 7800}, {"stiffness", 1e8}, {"restitution", 0.5}, {"reference_radius", 0.05},
                                    {"friction", 0.3}, {"tangential_damping_ratio", 0.5}}}}},
          {"balls", balls},
          {"walls", {wall}},
          {"time", {{"dt_per_contact_time", 0.02}, {"duration", 0.5}}},
          {"output", {{"series_interval", 0.01}, {"probes", {{{"type", "wall_load"}, {"name", "mill"}, {"wall", "mill"}}}}}}};
}

}  // namespace

TEST(Drum, FaceBallsSitBehindTheirFacesAndLiftersOnFaceMiddles) {
  const WallSpec w = drum(0.0);
  const auto balls = build_wall(w, 5);
  const double apothem = 1.0 * std::cos(M_PI / 24);
  int faces = 0, lifters = 0;
  for (const auto& b : balls) {
    const Vec3 d = b.position - w.centre;
    EXPECT_EQ(d.y(), 0.0);
    // Behind a face: the largest projection on the face normals is the apothem + r̄ exactly.
    double out = -INFINITY;
    for (int k = 0; k < 24; ++k) out = std::max(out, d.dot(Vec3(std::cos(2 * M_PI * (k + 0.5) / 24), 0, std::sin(2 * M_PI * (k + 0.5) / 24))));
    if (std::abs(out - (apothem + kR)) < 1e-12) {
      ++faces;
    } else {
      ++lifters;  // inside: on one of the 4 radii through face middles, within the lifter height
      const double angle = std::atan2(d.z(), d.x()) / (2 * M_PI) * 24 - 0.5;
      EXPECT_NEAR(angle / 6.0, std::round(angle / 6.0), 1e-9) << "a lifter ball off a face middle";
      EXPECT_GE(d.norm(), apothem - w.lifter_height - 1e-12);
    }
  }
  EXPECT_EQ(lifters, 4 * 6);  // h = 0, 0.02, … 0.1: the foot stands on the face, overlapping its balls
  EXPECT_GT(faces, int(2 * M_PI / kSpacing));
  // The ring's dips only: √((s/2)² + r²) − r = 0.118 r at s = r on a face, a little more at the
  // 15° corners (measured 0.133 r).
  EXPECT_LT(largest_hole(w, balls), 0.15 * kR);
}

TEST(Drum, APrismIsClosedAtItsEnds) {
  WallSpec w = drum(0.1);
  w.diameter = 0.4;
  w.lifters = 0;
  const auto balls = build_wall(w, 5);
  // A square net's dips, √(s²/2 + r²) − r = 0.22 r, and where a plate's grid meets the ring (measured
  // 0.30 r): no grain above a third of the wall balls' radius passes.
  EXPECT_LT(largest_hole(w, balls), 0.35 * kR);
  WallSpec loose = w;
  loose.spacing = 1.9 * kR;
  EXPECT_GT(largest_hole(loose, build_wall(loose, 5)), 0.45 * kR);
}

TEST(Drum, TheLoaderRefusesLiftersOffTheFacesOrReachingTheAxis) {
  EXPECT_EQ(refusal(mill_case(mill_wall())), "");
  json w = mill_wall();
  w["lifters"]["count"] = 5;
  EXPECT_NE(refusal(mill_case(w)).find("multiple of their count"), std::string::npos) << refusal(mill_case(w));
  w = mill_wall();
  w["lifters"]["height"] = 1.0;
  EXPECT_NE(refusal(mill_case(w)).find("reaches the axis"), std::string::npos) << refusal(mill_case(w));
  w = mill_wall();
  w["length"] = 0.2;
  EXPECT_NE(refusal(mill_case(w)).find("one row deep"), std::string::npos) << refusal(mill_case(w));
  w = mill_wall();
  w["motion"] = {{"rotation", {{"centre", {0, 0, 0}}, {"axis", {1, 0, 0}}, {"angular_speed", 3.0}}}};
  EXPECT_NE(refusal(mill_case(w)).find("out of the plane"), std::string::npos) << refusal(mill_case(w));
}

TEST(Drum, APlanarMillKeepsItsChargeAndClosesItsLedger) {
  // The thesis's mill (R = 1 m, 24 sides) at 3 rad/s with four lifters, 20 steel discs of r = 5 cm:
  // after 0.5 s every disc is still inside the ring and in the plane, and the ledger, with the wall's
  // work booked as injected energy, closes to 1e-2 (measured below 2e-3).
  json w = mill_wall();
  w["motion"] = {{"rotation", {{"centre", {0, 0, 0}}, {"axis", {0, 1, 0}}, {"angular_speed", 3.0}}}};
  const json s = silodem_test::run_in_scratch(mill_case(w), "silodem_drum_mill");
  EXPECT_EQ(s["balls"]["mobile"].get<int>(), 20);
  EXPECT_GT(s["energy"]["injected"].get<double>(), 0.0);
  EXPECT_LT(s["energy"]["max_abs_relative_drift"].get<double>(), 1e-2);
  std::ifstream in(std::filesystem::temp_directory_path() / "silodem_drum_mill" / "state.json");
  const json state = json::parse(in);
  int inside = 0;  // centre inside every face line, less at least half a radius (the overlap guard's limit)
  for (const auto& b : state["balls"]) {
    if (b["id"].get<std::string>()[0] != 'b') continue;
    const Vec3 x(b["position"][0].get<double>(), b["position"][1].get<double>(), b["position"][2].get<double>());
    double out = -INFINITY;
    for (int k = 0; k < 24; ++k) out = std::max(out, x.dot(Vec3(std::cos(2 * M_PI * (k + 0.5) / 24), 0, std::sin(2 * M_PI * (k + 0.5) / 24))));
    inside += out < std::cos(M_PI / 24) - 0.025 && x.y() == 0.0;
  }
  EXPECT_EQ(inside, 20);
}
