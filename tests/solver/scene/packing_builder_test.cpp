// Generated packings (scene/packing_builder.hpp, `generate` in a case): counts against closed
// forms, every grain inside its region, no two random grains overlapping (checked pair by pair,
// not through the builder's cell grid), the same grains for the same seed, and a region too small
// refused with how many fit.
#include <gtest/gtest.h>

#include <cmath>

#include "silodem/case/case_error.hpp"
#include "silodem/case/case_loader.hpp"
#include "silodem/scene/packing_builder.hpp"

using namespace silodem;
using nlohmann::json;

namespace {

PackingSpec box_lattice() {
  PackingSpec s;
  s.name = "g", s.kind = "lattice", s.material = "grain";
  s.r_min = s.r_max = 0.001;
  s.spacing = 0.0025;
  s.region.min = Vec3(0, 0, 0), s.region.max = Vec3(0.0201, 0.0101, 0.0301);
  return s;
}

}  // namespace

TEST(PackingBuilder, ABoxLatticeHasTheClosedFormCountBottomUp) {
  const PackingSpec s = box_lattice();
  // Sites along an edge of length L: floor((L − 2 r) / spacing) + 1.
  const auto sites = [&](double L) { return long(std::floor((L - 2 * s.r_max) / s.spacing)) + 1; };
  const auto balls = build_packing(s);
  ASSERT_EQ(long(balls.size()), sites(0.0201) * sites(0.0101) * sites(0.0301));
  EXPECT_EQ(balls.front().id, "g_0");
  EXPECT_EQ(balls.front().position, Vec3(0.001, 0.001, 0.001));
  for (std::size_t i = 1; i < balls.size(); ++i) EXPECT_LE(balls[i - 1].position.z(), balls[i].position.z());
  PackingSpec few = s;
  few.count = 10;
  EXPECT_EQ(build_packing(few).size(), 10u);
  few.count = 100000;
  try {
    build_packing(few);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("holds " + std::to_string(balls.size()) + " lattice sites"), std::string::npos);
  }
}

TEST(PackingBuilder, EveryGrainLiesInsideItsCylinderOrSilo) {
  for (const auto shape : {PackingRegion::Shape::Cylinder, PackingRegion::Shape::Silo}) {
    for (const std::string kind : {"lattice", "random"}) {
      PackingSpec s;
      s.name = "g", s.kind = kind, s.material = "grain";
      s.r_min = 0.0008, s.r_max = 0.001;
      s.spacing = 0.0021;
      s.count = kind == "random" ? 800 : -1;
      s.clearance = 0.0002;
      s.seed = 5;
      s.region.shape = shape;
      s.region.cx = 0.1, s.region.cy = -0.2, s.region.radius = 0.02;
      s.region.z_lo = 0.0, s.region.z_hi = 0.05;
      s.region.outlet_radius = 0.005, s.region.half_angle = 30.0 * kPi / 180.0;
      const auto balls = build_packing(s);
      ASSERT_GT(balls.size(), 100u);
      for (const auto& b : balls) {
        const double rho = std::hypot(b.position.x() - 0.1, b.position.y() + 0.2);
        EXPECT_LE(rho + b.radius + s.clearance, 0.02 + 1e-15);
        EXPECT_GE(b.position.z() - b.radius - s.clearance, -1e-15);
        EXPECT_LE(b.position.z() + b.radius + s.clearance, 0.05 + 1e-15);
        if (shape == PackingRegion::Shape::Silo) {
          // Normal distance to the cone's wall: (wall radius at this height − ρ) cos β.
          const double wall = 0.005 + b.position.z() * std::tan(s.region.half_angle);
          if (wall < 0.02) {
            EXPECT_GE((wall - rho) * std::cos(s.region.half_angle), b.radius + s.clearance - 1e-12);
          }
        }
      }
    }
  }
}

TEST(PackingBuilder, RandomGrainsNeverOverlapAndASeedFixesThem) {
  PackingSpec s;
  s.name = "r", s.kind = "random", s.material = "grain";
  s.r_min = 0.0005, s.r_max = 0.001;
  s.count = 1500, s.seed = 42;
  s.region.min = Vec3(-0.02, -0.02, 0.0), s.region.max = Vec3(0.02, 0.02, 0.02);
  const auto balls = build_packing(s);
  ASSERT_EQ(balls.size(), 1500u);
  double closest = INFINITY;
  for (std::size_t i = 0; i < balls.size(); ++i)
    for (std::size_t j = i + 1; j < balls.size(); ++j)
      closest = std::min(closest, (balls[i].position - balls[j].position).norm() - balls[i].radius - balls[j].radius);
  EXPECT_GE(closest, 0.0);
  const auto again = build_packing(s);
  for (std::size_t i = 0; i < balls.size(); ++i) EXPECT_EQ(balls[i].position, again[i].position);
  s.seed = 43;
  EXPECT_NE(build_packing(s)[0].position, balls[0].position);
  // A flat region of 4e6 m² a grain thick: the cell grid is sized by the grains, not the area.
  PackingSpec flat = s;
  flat.count = 1000;
  flat.region.min = Vec3(-1000, -1000, 0), flat.region.max = Vec3(1000, 1000, 0.002);
  EXPECT_EQ(build_packing(flat).size(), 1000u);
  // Random addition jams near a solid fraction of 0.38: far more grains than that cannot be placed.
  s.count = 20000;  // a solid fraction of 0.7 at these radii
  try {
    build_packing(s);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("placed"), std::string::npos) << e.what();
  }
}

TEST(PackingBuilder, TheCaseKeysAreCheckedAndNamedByTheirPath) {
  json c = json::parse(R"({
    "name": "gen", "materials": {"grain": {"density": 2500, "stiffness": 1e5, "restitution": 0.5, "reference_radius": 0.001}},
    "walls": [{"name": "floor", "type": "disk", "material": "grain", "radius": [0.001, 0.001], "spacing": 0.0015,
               "centre": [0, 0, 0], "diameter": 0.02}],
    "generate": [{"name": "g", "type": "lattice", "material": "grain", "radius": 0.001, "count": 27,
                  "region": {"shape": "box", "min": [-0.01, -0.01, 0.002], "max": [0.01, 0.01, 0.03]}}],
    "time": {"dt": 1e-5, "duration": 1e-3}})");
  const CaseConfig cfg = load_case(c);
  EXPECT_EQ(cfg.generated_balls, 27u);
  EXPECT_EQ(cfg.balls.back().id, "g_26");
  const auto refused = [&](const json& patch, const std::string& path, const std::string& words) {
    json bad = c;
    bad.merge_patch(patch);
    try {
      load_case(bad);
      ADD_FAILURE() << patch.dump();
    } catch (const CaseError& e) {
      EXPECT_EQ(e.path(), path) << e.what();
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  const auto gen = [&](const json& g) { json j = c["generate"][0]; j.merge_patch(g); return json{{"generate", {j}}}; };
  refused(gen({{"typo", 1}}), "$.generate[0].typo", "unknown key");
  refused(gen({{"material", "sand"}}), "$.generate[0].material", "no material");
  refused(gen({{"spacing", 0.0015}}), "$.generate[0].spacing", "out of range");
  refused(gen({{"name", "floor_x"}}), "$.generate[0].name", "id prefix");
  refused(gen({{"count", 100000}}), "$.generate[0].region", "lattice sites");
  refused(gen({{"type", "random"}, {"count", nullptr}}), "$.generate[0].count", "required");
  // Without a count, the sites are counted as the builder makes them (a flat box: one layer of
  // 20,001 × 20,001 sites, far above the limit), before any is made.
  refused(gen({{"count", nullptr}, {"spacing", 0.05}, {"region", {{"min", {0, 0, 0}}, {"max", {1000, 1000, 0.002}}}}}),
          "$.generate[0].spacing", "lattice sites");
  refused(gen({{"region", {{"shape", "cone"}}}}), "$.generate[0].region.shape", "unknown value");
}
