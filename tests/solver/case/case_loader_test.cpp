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

TEST(CaseLoader, FrictionKeysLoadAndMeaninglessCombinationsAreRefusedWithTheirPath) {
  // A valid frictional case: the keys reach the material, the pair table's inputs.
  const CaseConfig c = load_case([] {
    json j = minimal();
    j.merge_patch(json::parse(R"({"contact": {"tangential": "linear_history", "rolling": "constant_torque"},
      "materials": {"g": {"friction": 0.4, "rolling_friction": 0.01, "shear_stiffness_ratio": 0.5}},
      "material_pairs": [{"materials": ["g", "g"], "friction": 0.3}]})"));
    return j;
  }());
  EXPECT_EQ(c.contact.tangential, TangentialModel::LinearHistory);
  EXPECT_EQ(c.materials.at("g").friction, 0.4);
  EXPECT_EQ(c.materials.at("g").shear_stiffness_ratio, 0.5);
  ASSERT_EQ(c.contact.material_pairs.size(), 1u);
  EXPECT_EQ(*c.contact.material_pairs[0].friction, 0.3);
  // Each key no chosen law reads, and each combination that means nothing, names its path.
  EXPECT_EQ(error_path(json::parse(R"({"materials": {"g": {"friction": 0.4}}})")), "$.materials.g.friction");
  EXPECT_EQ(error_path(json::parse(R"({"contact": {"tangential": "mindlin"}})")), "$.contact.tangential");
  EXPECT_EQ(error_path(json::parse(R"({"contact": {"normal": "hertz", "tangential": "linear_history"}})")), "$.contact.tangential");
  EXPECT_EQ(error_path(json::parse(R"({"materials": {"g": {"rolling_damping_ratio": 0.3}}})")), "$.materials.g.rolling_damping_ratio");
  EXPECT_EQ(error_path(json::parse(R"({"contact": {"tangential": "coulomb_sliding"}, "materials": {"g": {"shear_stiffness_ratio": 1}}})")),
            "$.materials.g.shear_stiffness_ratio");
  EXPECT_EQ(error_path(json::parse(R"({"contact": {"normal": "hertz", "tangential": "mindlin", "cohesion": {"p_N": 0.1}}})")),
            "$.contact.cohesion");
  EXPECT_EQ(error_path(json::parse(R"({"contact": {"rolling": "spinning_top"}})")), "$.contact.rolling");
  EXPECT_EQ(error_path(json::parse(R"({"contact": {"slip_lever_arm": "radius"}})")), "$.contact.slip_lever_arm");
  EXPECT_EQ(error_path(json::parse(R"({"contact": {"tangential": "linear_history", "slip_lever_arm": "centre"}})")),
            "$.contact.slip_lever_arm");
  // The EPSD limit's form needs the EPSD spring, and is one of two names.
  EXPECT_EQ(error_path(json::parse(R"({"contact": {"rolling_limit": "spring_and_dashpot"}})")), "$.contact.rolling_limit");
  EXPECT_EQ(error_path(json::parse(R"({"contact": {"tangential": "linear_history", "rolling": "epsd", "rolling_limit": "both"}})")),
            "$.contact.rolling_limit");
  EXPECT_EQ(error_path(json::parse(R"({"balls": [{"id": "a", "material": "g", "radius": 0.005, "position": [0, 0, 0],
                                                  "angular_velocity": [0, 1, 0]}]})")),
            "$.balls[0].angular_velocity");
  EXPECT_EQ(error_path(json::parse(R"({"contact": {"tangential": "linear_history"}, "material_pairs": [{"materials": ["g", "steel"], "friction": 0.3}]})")),
            "$.material_pairs[0].materials");
  // Hertz: elastic constants instead of k, and a step of its own.
  EXPECT_EQ(error_path(json::parse(R"({"contact": {"normal": "hertz"}})")), "$.materials.g.stiffness");
  json hertz = json::parse(R"({"contact": {"normal": "hertz"}, "materials": {"g": {"stiffness": null, "damping": null,
    "youngs_modulus": 7e10, "poisson_ratio": 0.3, "restitution": 0.9}}, "time": {"dt": null, "dt_per_contact_time": 0.02}})");
  EXPECT_EQ(error_path(hertz), "$.time.dt");
}

TEST(CaseLoader, AStepStableForTheNormalModeButNotTheTangentialOneIsRefused) {
  // k_t = k_n (ρ = 1): the tangential mode runs at √3.5 ω0 (model.md §10.6). Undamped velocity
  // Verlet is stable for ω Δt < 2: Δt = 1.5/ω0 is stable for the normal mode, but ω_t Δt = 2.8.
  json j = minimal();
  const double m = 2500 * 4.0 / 3.0 * M_PI * std::pow(0.005, 3), k = 2e5;  // the wall pair: m_eff = m, k_ij = k/2
  const double dt = 1.5 / std::sqrt(0.5 * k / m);
  j.merge_patch({{"integrator", {{"scheme", "velocity_verlet"}}}, {"materials", {{"g", {{"damping", 0}}}}},
                 {"time", {{"dt", dt}, {"duration", 1000 * dt}}}});
  EXPECT_NO_THROW(load_case(j));
  j.merge_patch({{"contact", {{"tangential", "linear_history"}}}, {"materials", {{"g", {{"shear_stiffness_ratio", 1.0}}}}}});
  try {
    load_case(j);
    ADD_FAILURE() << "accepted";
  } catch (const CaseError& e) {
    EXPECT_EQ(e.path(), "$.time.dt");
  }
  // The default ρ = 2/7 gives the tangential mode the normal mode's frequency, Ω_t = 1.5. The
  // force law loads the spring with the predicted velocity, so the default velocity Verlet holds
  // the spring only to Ω_t < √2 (theory.md §7.7, measured in reports/stability.md): refused.
  j["materials"]["g"]["shear_stiffness_ratio"] = 2.0 / 7.0;
  EXPECT_THROW(load_case(j), CaseError);
  // With the half-step dashpot velocity the spring's limit is the normal mode's, Ω < 2: accepted.
  j["integrator"]["dashpot_velocity"] = "half_step";
  EXPECT_NO_THROW(load_case(j));
}

namespace {

/// A glass sphere (r = 5 mm, E = 70 GPa, ν = 0.25, e = 1) at 1 m/s onto a plane (a fixed ball of
/// radius 1000 m, E = 10 TPa), no gravity, Hertz.
json hertz_drop(double dt, const std::string& tangential) {
  json j = json::parse(R"({
    "name": "hertz_dt", "gravity": [0, 0, 0], "contact": {"normal": "hertz"},
    "materials": {"glass": {"density": 2500, "youngs_modulus": 7e10, "poisson_ratio": 0.25, "restitution": 1.0},
                  "plane": {"density": 7800, "youngs_modulus": 1e13, "poisson_ratio": 0.3, "restitution": 1.0}},
    "balls": [{"id": "a", "material": "glass", "radius": 0.005, "position": [0, 0, 1000.006], "velocity": [0, 0, -1]},
              {"id": "p", "material": "plane", "radius": 1000, "position": [0, 0, 0], "fixed": true}],
    "integrator": {"scheme": "velocity_verlet"}, "time": {"duration": 1e-3}})");
  j["time"]["dt"] = dt;
  if (!tangential.empty()) j["contact"]["tangential"] = tangential;
  return j;
}

/// The peak of that impact (Johnson 1985 §11.4): δ_max from ½ m v² = 8/15 E*√R* δ^{5/2}, the tangent
/// stiffness 2E*√(R*δ) there, and its frequency on the ball's mass.
double hertz_drop_omega() {
  const double r = 0.005, big = 1000.0, m = 2500 * 4.0 / 3.0 * M_PI * r * r * r, v = 1.0;
  const double e_star = 1.0 / ((1 - 0.25 * 0.25) / 7e10 + (1 - 0.3 * 0.3) / 1e13), r_star = r * big / (r + big);
  const double delta = std::pow(15.0 * m * v * v / (16.0 * e_star * std::sqrt(r_star)), 0.4);
  return std::sqrt(2.0 * e_star * std::sqrt(r_star * delta) / m);
}

std::string refusal(const json& j) {
  try {
    load_case(j);
  } catch (const CaseError& e) {
    return e.path() + ": " + e.what();
  }
  return "accepted";
}

}  // namespace

TEST(CaseLoader, AHertzStepAboveTheLimitAtTheImpactsPeakStiffnessIsRefused) {
  // Undamped velocity Verlet is stable for ω Δt < 2 (theory.md §7.3), here with ω at the deepest
  // overlap of the fastest impact the scene holds (theory.md §10.9).
  const double limit = 2.0 / hertz_drop_omega();
  EXPECT_EQ(refusal(hertz_drop(0.99 * limit, "")), "accepted");
  const std::string no = refusal(hertz_drop(1.01 * limit, ""));
  EXPECT_EQ(no.rfind("$.time.dt: ", 0), 0u) << no;
  EXPECT_NE(no.find("normal mode at the peak of an impact at 1 m/s"), std::string::npos) << no;
  // The same limit as a fraction of the impact's duration: 2/(√(15/8) · 2.9432) = 0.4962 t_c.
  EXPECT_NE(no.find("so the limit is 0.496"), std::string::npos) << no;
  // Mindlin's k_t = 8G*√(R*δ) on 2/7 m runs at √(14 G*/E*) times the normal frequency, stiffer for
  // every ν: the same step is refused for the tangential mode.
  const std::string t = refusal(hertz_drop(0.99 * limit, "mindlin"));
  EXPECT_EQ(t.rfind("$.time.dt: ", 0), 0u) << t;
  EXPECT_NE(t.find("Mindlin tangential mode"), std::string::npos) << t;
  const double g_star = 1.0 / (2 * (2 - 0.25) * 1.25 / 7e10 + 2 * (2 - 0.3) * 1.3 / 1e13);
  const double e_star = 1.0 / ((1 - 0.25 * 0.25) / 7e10 + (1 - 0.3 * 0.3) / 1e13);
  // A history spring grown by the force law: velocity Verlet holds it to ω_t Δt < √2 (theory.md §7.7).
  const double t_limit = std::sqrt(2.0) / 2.0 * limit / std::sqrt(14.0 * g_star / e_star);
  EXPECT_EQ(refusal(hertz_drop(0.99 * t_limit, "mindlin")), "accepted");
  EXPECT_NE(refusal(hertz_drop(1.01 * t_limit, "mindlin")), "accepted");
}

TEST(CaseLoader, AHertzBallAtRestTakesItsApproachSpeedFromTheFreeFall) {
  // At rest with its centre 0.055 m above the plane's top, under g: the bound takes the fall from
  // its own top to the plane's, h = 0.06 m (one radius more than the centre falls), v = √(2 g h).
  json j = hertz_drop(1e-7, "");
  j["gravity"] = {0.0, 0.0, -9.81};
  j["balls"][0]["position"] = {0.0, 0.0, 1000.055};
  j["balls"][0]["velocity"] = {0.0, 0.0, 0.0};
  const double h = 1000.055 + 0.005 - 1000.0, v = std::sqrt(2 * 9.81 * h);
  // ω of the peak grows as v^{1/5} (δ_max ∝ v^{4/5}, ω = √(15/8) v/δ_max).
  const double limit = 2.0 / (hertz_drop_omega() * std::pow(v, 0.2));
  j["time"]["dt"] = 0.99 * limit;
  EXPECT_EQ(refusal(j), "accepted");
  j["time"]["dt"] = 1.01 * limit;
  const std::string no = refusal(j);
  EXPECT_NE(no.find("impact at 1.0849"), std::string::npos) << no;  // √(2 · 9.81 · 0.06) = 1.08499 m/s
}

TEST(CaseLoader, TheHertzCasesLoadInEveryVariant) {
  // Chung & Ooi's impacts run at t_c/1000 and t_c/350, far below the limit of about t_c/2.
  for (const char* name : {"chung_ooi_normal_impact", "chung_ooi_oblique_impact"}) {
    const json c = read_case_json(std::string(SILODEM_SOURCE_DIR) + "/cases/" + name + ".json");
    EXPECT_NO_THROW(load_case(c)) << name;
    for (const auto& [axis, values] : c["verify"]["variants"].items())
      for (const auto& [label, patch] : values.items()) {
        json v = c;
        v.merge_patch(patch);
        EXPECT_NO_THROW(load_case(v)) << name << " " << axis << "=" << label;
      }
  }
}
