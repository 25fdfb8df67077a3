// Case-file validation: good input loads with its derived constants, bad input is refused with the
// JSON path of the offending field.
#include <gtest/gtest.h>

#include <cmath>

#include "silodem/case/case_error.hpp"
#include "silodem/case/case_loader.hpp"

using namespace silodem;
using nlohmann::json;

namespace {

json minimal() {
  return json::parse(R"({
    "name": "t",
    "materials": {"g": {"density": 2500, "stiffness": 2e5, "damping": 6}},
    "balls": [{"id": "a", "material": "g", "radius": 0.005, "position": [0, 0, 0]},
              {"id": "w", "material": "g", "radius": 0.005, "position": [0, 0, -0.01], "fixed": true}],
    "time": {"dt": 1e-6, "duration": 1e-3}
  })");
}

/// Applies `patch` (RFC 7386) to the minimal case and returns the error path.
std::string error_path(const json& patch) {
  json j = minimal();
  j.merge_patch(patch);
  try {
    load_case(j);
  } catch (const CaseError& e) {
    return e.path();
  }
  return "accepted";
}

}  // namespace

TEST(CaseLoader, MinimalCaseLoadsWithDefaults) {
  const CaseConfig c = load_case(minimal());
  EXPECT_EQ(c.balls.size(), 2u);
  EXPECT_TRUE(c.balls[1].fixed);
  EXPECT_EQ(c.gravity, Vec3(0, 0, -9.81));
  EXPECT_EQ(c.integrator.scheme, kDefaultScheme);  // from the work–precision front (case_config.hpp)
  EXPECT_FALSE(c.contact.clamp);
  EXPECT_DOUBLE_EQ(c.materials.at("g").k, 2e5);
}

TEST(CaseLoader, WithoutAStepTheDefaultFractionOfTheContactTime) {
  json j = minimal();
  j["time"] = {{"duration", 0.01}};
  const CaseConfig c = load_case(j);
  ASSERT_TRUE(c.dt_per_contact_time.has_value());
  EXPECT_EQ(*c.dt_per_contact_time, kDefaultDtPerContactTime);
  // Ball on a wall ball: k_ij = 1e5, c_ij = 3, m_eff = the ball's mass; t_c of the damped oscillator.
  const double m = 2500.0 * 4.0 / 3.0 * kPi * 0.005 * 0.005 * 0.005, w0 = std::sqrt(1e5 / m), z = 3.0 / (2.0 * std::sqrt(1e5 * m));
  EXPECT_NEAR(c.dt, kDefaultDtPerContactTime * kPi / (w0 * std::sqrt(1.0 - z * z)), 1e-12);
  j["time"] = {{"duration", 0.01}, {"dt", 1e-6}, {"dt_per_contact_time", 0.02}};
  EXPECT_EQ(error_path(j), "$.time");
}

TEST(CaseLoader, DerivesConstantsFromContactTimeAndRestitution) {
  json j = minimal();
  j["materials"]["g"] = {{"density", 2500}, {"contact_time", 2.586429e-4}, {"restitution", 0.552796},
                         {"reference_radius", 0.005}};
  const CaseConfig c = load_case(j);
  // the test pair of docs/reference-codes.md: this pair is k = 1e5, c = 3 → per ball 2e5, 6.
  EXPECT_NEAR(c.materials.at("g").k, 2e5, 2.0);
  EXPECT_NEAR(c.materials.at("g").c, 6.0, 1e-4);
}

TEST(CaseLoader, DtPerContactTimeUsesTheStiffestPair) {
  json j = minimal();
  j["time"] = {{"dt_per_contact_time", 0.02}, {"duration", 1e-3}};
  const CaseConfig c = load_case(j);
  // One mobile ball on a wall ball: m_eff = m, k = 1e5, c = 3.
  const double m = 2500 * 4.0 / 3.0 * M_PI * 1.25e-7, w0 = std::sqrt(1e5 / m), z = 3.0 / (2 * std::sqrt(1e5 * m));
  EXPECT_NEAR(c.dt, 0.02 * M_PI / (w0 * std::sqrt(1 - z * z)), 1e-15);
}

TEST(CaseLoader, RejectsBadInputNamingThePath) {
  EXPECT_EQ(error_path({{"balls", {{{"id", "a"}, {"material", "g"}, {"radius", -1.0}, {"position", {0, 0, 0}}}}}}),
            "$.balls[0].radius");
  EXPECT_EQ(error_path({{"time", {{"dt", 0.0}}}}), "$.time.dt");
  EXPECT_EQ(error_path({{"time", {{"dt", "1e-6"}}}}), "$.time.dt");
  EXPECT_EQ(error_path({{"materials", {{"g", {{"stiffness", 0.0}}}}}}), "$.materials.g.stiffness");
  EXPECT_EQ(error_path({{"materials", {{"g", {{"damping", nullptr}}}}}}), "$.materials.g");
  EXPECT_EQ(error_path({{"balls", {{{"id", "a"}, {"material", "nope"}, {"radius", 0.01}, {"position", {0, 0, 0}}}}}}),
            "$.balls[0].material");
  EXPECT_EQ(error_path({{"balls", {{{"id", "a"}, {"material", "g"}, {"radius", 0.01}, {"position", {0, 0}}}}}}),
            "$.balls[0].position");
  EXPECT_EQ(error_path({{"drops", {{"material", "g"}, {"radius", {0.006, 0.004}}, {"z0", 1}, {"count", 3},
                                   {"inlet", {{"x", {0, 1}}, {"y", {0, 1}}}}}}}),
            "$.drops.radius");  // r_min > r_max
  EXPECT_EQ(error_path({{"integrator", {{"scheme", "rk4"}}}}), "$.integrator.scheme");
  EXPECT_EQ(error_path({{"time", {{"duration", nullptr}}}}), "$.time.duration");  // missing
  EXPECT_EQ(error_path({{"name", 3}}), "$.name");
  json no_mobile = minimal();
  no_mobile["balls"][0]["fixed"] = true;
  EXPECT_THROW(load_case(no_mobile), CaseError);
}

TEST(CaseLoader, UnknownKeyGetsADidYouMeanHint) {
  json j = minimal();
  j["time"]["duraton"] = 1.0;
  try {
    load_case(j);
    FAIL() << "accepted a misspelt key";
  } catch (const CaseError& e) {
    EXPECT_EQ(e.path(), "$.time.duraton");
    EXPECT_NE(std::string(e.what()).find("did you mean \"duration\""), std::string::npos) << e.what();
  }
}

TEST(CaseLoader, DropsNeedRoomAndDownwardGravity) {
  const json drops = {{"material", "g"}, {"radius", {0.004, 0.005}}, {"z0", 0.1}, {"count", 3},
                      {"inlet", {{"x", {0, 0.01}}, {"y", {0, 0.01}}}}};
  EXPECT_EQ(error_path({{"drops", drops}}), "accepted");
  json high = drops;
  high["z0"] = -0.001;  // below the mobile ball at z = 0
  EXPECT_EQ(error_path({{"drops", high}}), "$.drops.z0");
  EXPECT_EQ(error_path({{"drops", drops}, {"gravity", {9.81, 0, 0}}}), "$.gravity");
}

TEST(CaseLoader, ReleasedDropsFollowAFixedSequence) {
  json drops = {{"material", "g"}, {"radius", {0.004, 0.005}}, {"z0", 0.1}, {"count", 3},
                {"inlet", {{"x", {0, 0.01}}, {"y", {0, 0.01}}}}, {"placement", "release"}, {"release_speed", 1.5}};
  EXPECT_EQ(error_path({{"drops", drops}}), "accepted");
  json full = drops;
  full["full_level"] = 0.05;  // the fill height would end the sequence at a different drop per code
  EXPECT_EQ(error_path({{"drops", full}}), "$.drops.full_level");
  json velocity = drops;
  velocity["initial_velocity"] = "zero";
  EXPECT_EQ(error_path({{"drops", velocity}}), "$.drops.initial_velocity");
  json negative = drops;
  negative["release_speed"] = -1.0;
  EXPECT_EQ(error_path({{"drops", negative}}), "$.drops.release_speed");
  json first_contact = drops;
  first_contact.erase("placement");
  EXPECT_EQ(error_path({{"drops", first_contact}}), "$.drops.release_speed");
  EXPECT_EQ(error_path({{"drops", drops}, {"stages", {{"outflow", {{"below_z", -1.0}}}}}}), "$.stages.outflow.mode");
  EXPECT_EQ(error_path({{"drops", drops}, {"stages", {{"outflow", {{"below_z", -1.0}, {"mode", "remove"}}}}}}),
            "accepted");
  const CaseConfig c = [&] {
    json j = minimal();
    j["drops"] = drops;
    return load_case(j);
  }();
  EXPECT_TRUE(c.drops->release);
  EXPECT_EQ(c.drops->release_speed, 1.5);
  EXPECT_FALSE(c.drops->free_fall_velocity);
}
