// Smooth walls (scene/surface.hpp, forces/surface_contacts.cpp) against closed forms and against
// another algorithm: the nearest-point geometry by hand; a sphere on the inside of a 45° hopper
// slides at g(sin α − μ cos α) when μ < 2/7 tan α and rolls at 5/7 g sin α otherwise (Goldstein's
// rolling-sphere result); an impact on a disk surface gives the same rebound, spin and restitution
// as the same impact on a fixed ball of radius 10^4 r; a ball at rest loads the surface with its
// weight; threads change no bit of a hopper that discharges through a smooth cone.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "silodem/case/case_error.hpp"
#include "silodem/case/case_loader.hpp"
#include "silodem/core/parallel.hpp"
#include "silodem/output/state_file.hpp"
#include "silodem/run/simulation.hpp"
#include "silodem/scene/surface.hpp"

namespace fs = std::filesystem;
using nlohmann::json;
using silodem::Vec3;

namespace {

constexpr double kG = 9.81, kR = 0.002, kRho = 2500.0;

json hertz_materials(double mu) {
  return {{"grain", {{"density", kRho}, {"youngs_modulus", 1e8}, {"poisson_ratio", 0.25}, {"restitution", 0.5}, {"friction", mu}}},
          {"steel", {{"density", 7800}, {"youngs_modulus", 2e11}, {"poisson_ratio", 0.3}, {"restitution", 0.5}, {"friction", mu}}}};
}

/// E* of the grain–steel pair (Hertz: 1/E* = Σ (1 − ν²)/E).
double e_star() { return 1.0 / ((1.0 - 0.25 * 0.25) / 1e8 + (1.0 - 0.3 * 0.3) / 2e11); }

json run(const json& c, const std::string& tag) {
  const fs::path out = fs::temp_directory_path() / ("silodem_surface_" + tag);
  fs::remove_all(out);  // the test's own scratch
  json s = silodem::run_case(silodem::load_case(c), {out, false, false});
  s["state"] = json::parse(std::ifstream(out / "state.json"));
  fs::remove_all(out);
  return s;
}

Vec3 ball_vec(const json& s, const std::string& key) {
  const json& b = s["state"]["balls"][0];
  return {b[key][0].get<double>(), b[key][1].get<double>(), b[key][2].get<double>()};
}

/// A ball on the inside of a 45° hopper (cone segment from ρ 0.02, z 0 to ρ 0.12, z 0.1), in the
/// meridian plane y = 0, pressed in by its static overlap so that it starts in equilibrium normally.
json hopper_ball(double mu, double duration) {
  const double m = kRho * 4.0 / 3.0 * M_PI * std::pow(kR, 3), f_n = m * kG * std::sqrt(0.5);
  const double overlap = std::pow(3.0 * f_n / (4.0 * e_star() * std::sqrt(kR)), 2.0 / 3.0);
  const double s = kR - overlap;  // centre distance from the surface
  return {{"name", "hopper_ball"},
          {"contact", {{"normal", "hertz"}, {"tangential", "mindlin"}}},
          {"materials", hertz_materials(mu)},
          {"surfaces", {{{"name", "cone"}, {"material", "steel"}, {"axis", {0, 0}}, {"profile", {{0.02, 0.0}, {0.12, 0.1}}}}}},
          {"balls", {{{"id", "b"}, {"material", "grain"}, {"radius", kR},
                      {"position", {0.08 - s * std::sqrt(0.5), 0.0, 0.06 + s * std::sqrt(0.5)}}}}},
          {"time", {{"dt", 2e-6}, {"duration", duration}}}};
}

/// Distance travelled down the generatrix.
double downhill(const json& s) {
  const Vec3 x = ball_vec(s, "position");
  const json& x0 = s["input"]["balls"][0]["position"];
  return ((x0[0].get<double>() - x.x()) + (x0[2].get<double>() - x.z())) * std::sqrt(0.5);
}

}  // namespace

silodem::Surface vertical(double x, double y, double rho0, double z0, double rho1, double z1) {
  silodem::Surface s;
  s.centre = {x, y, 0.0};
  s.rho0 = rho0, s.z0 = z0, s.rho1 = rho1, s.z1 = z1;
  return s;
}

TEST(SurfaceGap, CylinderConeAndTheRoundedRimByHand) {
  const silodem::Surface cyl = vertical(1.0, 2.0, 0.1, 0.0, 0.1, 0.5);
  auto g = silodem::surface_gap(cyl, {1.03, 2.04, 0.2});  // ρ = 0.05 inside
  EXPECT_NEAR(g.distance, 0.05, 1e-15);
  EXPECT_NEAR(g.n.x(), -0.6, 1e-15);  // towards the axis
  EXPECT_NEAR(g.n.y(), -0.8, 1e-15);
  g = silodem::surface_gap(cyl, {1.0, 2.1, 0.6});  // above the top rim: to the rim circle
  EXPECT_NEAR(g.distance, 0.1, 1e-15);
  EXPECT_NEAR(g.n.z(), 1.0, 1e-15);
  const silodem::Surface cone = vertical(0.0, 0.0, 0.02, 0.0, 0.12, 0.1);  // 45°
  g = silodem::surface_gap(cone, {0.0, 0.05, 0.05});  // ρ 0.05, z 0.05: (0.05 − 0.03 − 0.0)/√2 inside
  EXPECT_NEAR(g.distance, 0.02 / std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(g.n.y(), -std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(g.n.z(), std::sqrt(0.5), 1e-15);
  g = silodem::surface_gap(cone, {0.0, 0.0, -0.03});  // on the axis below the outlet: the rim circle
  EXPECT_NEAR(g.distance, std::hypot(0.02, 0.03), 1e-15);
  const silodem::Surface disk = vertical(0.0, 0.0, 0.0, 0.0, 0.3, 0.0);
  EXPECT_NEAR(silodem::surface_gap(disk, {0.1, -0.1, 0.004}).distance, 0.004, 1e-15);
  EXPECT_NEAR(silodem::surface_gap(disk, {0.1, -0.1, -0.004}).n.z(), -1.0, 1e-15);  // either side
}

// A drum about a horizontal axis (x, through (0, 1, 0)): ρ across it, z along it; its velocity
// spinning at Ω is Ω x̂ × (x − c).
TEST(SurfaceGap, AHorizontalDrumByHand) {
  silodem::Surface drum;
  drum.centre = {0.0, 1.0, 0.0}, drum.axis = Vec3::UnitX(), drum.across = silodem::perpendicular_to(drum.axis);
  drum.rho0 = drum.rho1 = 0.1, drum.z0 = 0.0, drum.z1 = 0.5, drum.angular_speed = 2.0;
  const auto g = silodem::surface_gap(drum, {0.2, 1.03, 0.04});  // ρ = 0.05 inside
  EXPECT_NEAR(g.distance, 0.05, 1e-15);
  EXPECT_NEAR(g.n.x(), 0.0, 1e-15);
  EXPECT_NEAR(g.n.y(), -0.6, 1e-15);
  EXPECT_NEAR(g.n.z(), -0.8, 1e-15);
  EXPECT_NEAR(silodem::surface_gap(drum, {-0.1, 1.0, 0.1}).distance, 0.1, 1e-15);  // past the end: the rim
  const Vec3 v = silodem::surface_velocity(drum, {0.3, 1.0, -0.1});  // the bottom moves along +y
  EXPECT_NEAR(v.y(), 0.2, 1e-15);
  EXPECT_NEAR(v.norm(), 0.2, 1e-15);
  EXPECT_NEAR(drum.across.dot(drum.axis), 0.0, 1e-15);
}

TEST(SurfaceContacts, ABallSlidesDownTheHopperAtGSinMinusMuCos) {
  const double mu = 0.2, t = 0.04;  // μ < 2/7 tan 45°: slides throughout
  const json s = run(hopper_ball(mu, t), "slide");
  const double a = kG * (std::sqrt(0.5) - mu * std::sqrt(0.5));
  EXPECT_NEAR(downhill(s), 0.5 * a * t * t, 0.005 * 0.5 * a * t * t);
  EXPECT_LT(std::abs(s["energy"]["max_abs_relative_drift"].get<double>()), 1e-3);
  EXPECT_GT(s["energy"]["dissipated"].get<double>(), 0.0);  // friction took energy
}

TEST(SurfaceContacts, ABallRollsDownTheHopperAtFiveSeventhsGSin) {
  const double t = 0.04;  // μ 0.5 > 2/7 tan 45°: rolls without slipping
  const json s = run(hopper_ball(0.5, t), "roll");
  const double a = 5.0 / 7.0 * kG * std::sqrt(0.5);
  EXPECT_NEAR(downhill(s), 0.5 * a * t * t, 0.005 * 0.5 * a * t * t);
  const Vec3 v = ball_vec(s, "velocity"), w = ball_vec(s, "angular_velocity");
  EXPECT_NEAR(w.norm() * kR, v.norm(), 0.005 * v.norm());  // ω r = v: no slip
}

TEST(SurfaceContacts, AnImpactOnADiskIsTheImpactOnAHugeFixedBall) {
  const double big = 1e4 * kR;
  const json v0 = {0.6, 0.0, -1.0};
  json with_surface = {{"name", "impact"},
                       {"gravity", {0, 0, 0}},
                       {"contact", {{"normal", "hertz"}, {"tangential", "mindlin"}}},
                       {"materials", hertz_materials(0.3)},
                       {"surfaces", {{{"name", "floor"}, {"material", "steel"}, {"axis", {0, 0}}, {"profile", {{0.0, 0.0}, {1.0, 0.0}}}}}},
                       {"balls", {{{"id", "b"}, {"material", "grain"}, {"radius", kR}, {"position", {0, 0, kR * 1.01}}, {"velocity", v0}}}},
                       {"time", {{"dt", 1e-7}, {"duration", 2e-4}}}};
  json with_ball = with_surface;
  with_ball.erase("surfaces");
  with_ball["balls"].push_back({{"id", "plane"}, {"material", "steel"}, {"radius", big}, {"position", {0, 0, -big}}, {"fixed", true}});
  const json a = run(with_surface, "disk"), b = run(with_ball, "bigball");
  const Vec3 va = ball_vec(a, "velocity"), vb = ball_vec(b, "velocity");
  const Vec3 wa = ball_vec(a, "angular_velocity"), wb = ball_vec(b, "angular_velocity");
  ASSERT_GT(va.z(), 0.0);  // it rebounded
  EXPECT_NEAR(va.z(), vb.z(), 1e-4 * std::abs(vb.z()));  // R* differs by r/R = 1e-4
  EXPECT_NEAR(va.x(), vb.x(), 1e-4 * std::abs(vb.x()));
  EXPECT_NEAR(wa.y(), wb.y(), 1e-4 * std::abs(wb.y()));
  EXPECT_NEAR(va.z() / 1.0, 0.5, 0.01);  // the pair's restitution (both materials e = 0.5)
  EXPECT_LT(std::abs(a["energy"]["max_abs_relative_drift"].get<double>()), 1e-3);
}

TEST(SurfaceContacts, ABallAtRestLoadsTheSurfaceWithItsWeight) {
  json c = hopper_ball(0.5, 0.05);
  c["surfaces"] = {{{"name", "floor"}, {"material", "steel"}, {"axis", {0, 0}}, {"profile", {{0.0, 0.0}, {0.05, 0.0}}}}};
  c["balls"][0]["position"] = {0.01, 0.0, kR};
  const json s = run(c, "rest");
  const double w = kRho * 4.0 / 3.0 * M_PI * std::pow(kR, 3) * kG;
  EXPECT_NEAR(s["surface_loads"]["floor"][2].get<double>(), -w, 1e-4 * w);
  EXPECT_NEAR(s["wall_force"][2].get<double>(), -w, 1e-4 * w);
}

TEST(SurfaceContacts, AProfileOfThreePointsIsTwoSurfacesAndBadOnesAreRefused) {
  json c = hopper_ball(0.3, 0.001);
  c["surfaces"][0]["profile"] = {{0.12, 0.3}, {0.12, 0.1}, {0.02, 0.0}};
  const silodem::CaseConfig cfg = silodem::load_case(c);
  ASSERT_EQ(cfg.surfaces.size(), 2u);
  EXPECT_EQ(cfg.surfaces[1].name, "cone_1");
  const auto refused = [&](json bad, const std::string& words) {
    try {
      silodem::load_case(bad);
      ADD_FAILURE() << "accepted: " << bad["surfaces"].dump();
    } catch (const silodem::CaseError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  json bad = c;
  bad["surfaces"][0]["profile"] = {{0.1, 0.0}};
  refused(bad, "at least two points");
  bad = c;
  bad["surfaces"][0]["material"] = "glass";
  refused(bad, "no material named \"glass\"");
  bad = c;
  bad["balls"][0]["position"] = {0.07, 0.0, 0.05};  // the centre on the cone itself
  refused(bad, "deep in surface \"cone_1\"");
}

TEST(SurfaceContacts, ThreadsChangeNoBitOfAHopperDischarge) {
  json balls = json::array();
  int n = 0;
  for (int i = -4; i <= 4; ++i)
    for (int j = -4; j <= 4; ++j)
      for (int k = 0; k < 12; ++k)
        if (i * i + j * j <= 16)
          balls.push_back({{"id", "b" + std::to_string(n++)}, {"material", "grain"}, {"radius", 0.0045 + 0.0005 * ((i + j + k) % 2)},
                           {"position", {i * 0.0105, j * 0.0105, 0.07 + k * 0.0105}}});
  const json c = {{"name", "hopper_threads"},
                  {"contact", {{"normal", "hertz"}, {"tangential", "mindlin"}}},
                  {"materials", hertz_materials(0.3)},
                  {"surfaces", {{{"name", "silo"}, {"material", "steel"}, {"axis", {0, 0}},
                                 {"profile", {{0.06, 0.2}, {0.06, 0.04}, {0.02, 0.0}}}}}},
                  {"balls", balls},
                  {"stages", {{"outflow", {{"below_z", -0.02}, {"mode", "remove"}}}}},
                  {"time", {{"dt", 5e-6}, {"duration", 0.15}}}};
  const silodem::CaseConfig cfg = silodem::load_case(c);
  ASSERT_GT(balls.size(), 500u);  // more than one chunk of kSumChunk balls
  silodem::set_threads(2);
  const json two = run(c, "threads2");
  silodem::set_threads(1);
  const json one = run(c, "threads1");
  EXPECT_LT(one["balls"]["mobile"].get<int>(), int(balls.size()));  // some left through the outlet
  EXPECT_EQ(one["state"]["balls"].dump(), two["state"]["balls"].dump());
  EXPECT_EQ(one["surface_loads"].dump(), two["surface_loads"].dump());
  EXPECT_EQ(one["energy"].dump(), two["energy"].dump());
}
