// Friction through the reference backends (issue 28): each code's input carries the solver's own
// pair constants (k_t, tangential damping, μ per type pair, grain–wall μ from material_pairs), the
// initial spin, and a dump with ω; what a code cannot represent is refused with its reason.
#include <cstring>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>

#include "deck_helpers.hpp"
#include "harness/backends/reference_backend.hpp"
#include "harness/backends/translation.hpp"
#include "silodem/case/case_loader.hpp"

using namespace harness;
using nlohmann::json;

namespace {

/// A spinning ball of material "a" on a fixed ball of material "b"; grain–grain μ 0.5, grain–wall
/// μ 0.3 (material_pairs), history spring k_t = 0.4 k_n, tangential dashpot 0.25 c_n.
json frictional() {
  return json::parse(R"({
    "name": "deck",
    "contact": {"tangential": "linear_history", "clamp_tensile_force": true},
    "material_pairs": [{"materials": ["a", "b"], "friction": 0.3}],
    "materials": {"a": {"density": 2500, "stiffness": 2e5, "damping": 6, "friction": 0.5,
                        "shear_stiffness_ratio": 0.4, "tangential_damping_ratio": 0.25},
                  "b": {"density": 7800, "stiffness": 4e5, "damping": 2, "friction": 0.5,
                        "shear_stiffness_ratio": 0.4, "tangential_damping_ratio": 0.25}},
    "balls": [{"id": "m", "material": "a", "radius": 0.005, "position": [0, 0, 0.02], "velocity": [0.1, 0, -0.1],
               "angular_velocity": [0, 20, 0]},
              {"id": "w", "material": "b", "radius": 0.004, "position": [0, 0, 0], "fixed": true}],
    "integrator": {"scheme": "velocity_verlet", "dashpot_velocity": "half_step"},
    "time": {"dt": 2e-6, "duration": 1e-3},
    "output": {"dump_interval_steps": 5}
  })");
}

/// The same scene under the seeds' sliding law: gamma_t = 4 N s/m per material, no spring.
json sliding() {
  json c = frictional();
  c["contact"] = {{"tangential", "coulomb_sliding"}};
  c.erase("material_pairs");
  for (auto& [name, m] : c["materials"].items()) {
    m.erase("shear_stiffness_ratio");
    m.erase("tangential_damping_ratio");
    m["tangential_damping"] = 4.0;
  }
  return c;
}

using deck_helpers::file;
using deck_helpers::has;

ReferenceBackend::Input lammps_input(const silodem::CaseConfig& cfg) {
  std::string why;
  const auto backend = make_lammps_backend();
  EXPECT_EQ(backend->not_representable(cfg), "");
  return dynamic_cast<const ReferenceBackend&>(*backend).write_input(cfg, translate(cfg, why));
}

}  // namespace

TEST(LammpsFriction, HistorySpringPerTypePairWithGrainWallFriction) {
  const auto in = lammps_input(silodem::load_case(frictional()));
  const std::string& deck = file(in, "in.lammps");
  // k_11 = 1e5, k_t = 0.4 k_11; x_gamma = gamma_t / c_n = 0.25; mu 0.5 between grains.
  EXPECT_TRUE(has(deck, "pair_coeff 1 1 hooke 100000 3 tangential linear_history 40000 0.25 0.5 damping velocity limit_damping\n"));
  // Grain–wall: k_12 = 1.333e5, mu 0.3 from material_pairs.
  EXPECT_TRUE(has(deck, "pair_coeff 1 2 hooke 133333.33333333334 1.5 tangential linear_history 53333.333333333343 0.25 0.29999999999999999 damping velocity"));
  EXPECT_TRUE(has(deck, "fix integrate mobile nve/sphere"));
  EXPECT_TRUE(has(deck, " v_fixed omegax omegay omegaz\n"));
  // The initial spin, in the data file's Velocities section (id vx vy vz wx wy wz).
  EXPECT_TRUE(has(file(in, "data.lmp"), "1 0.10000000000000001 0 -0.10000000000000001 0 20 0\n"));
}

TEST(LammpsFriction, SlidingLawScalesTheNormalDashpot) {
  const json c = sliding();
  const std::string deck = file(lammps_input(silodem::load_case(c)), "in.lammps");
  // gamma_t = series(4, 4) = 2 against c_11 = 3: x_gamma = 2/3.
  EXPECT_TRUE(has(deck, "pair_coeff 1 1 hooke 100000 3 tangential linear_nohistory 0.66666666666666663 0.5 damping velocity\n"));
}

TEST(LammpsFriction, FrictionlessDeckIsUnchanged) {
  json c = frictional();
  c["contact"] = json::object();
  c.erase("material_pairs");
  for (auto& [name, m] : c["materials"].items()) m = {{"density", m["density"]}, {"stiffness", m["stiffness"]}, {"damping", m["damping"]}};
  c["balls"][0].erase("angular_velocity");
  const auto in = lammps_input(silodem::load_case(c));
  EXPECT_TRUE(has(file(in, "in.lammps"), "tangential linear_nohistory 0 0 damping velocity\n"));
  EXPECT_TRUE(has(file(in, "in.lammps"), " v_fixed\n"));  // no ω columns in a frictionless dump
}

TEST(FrictionRepresentability, UntranslatedSubModelsAreRefusedWithTheirReason) {
  json roll = frictional();
  roll["contact"]["rolling"] = "constant_torque";
  for (auto& [name, m] : roll["materials"].items()) m["rolling_friction"] = 0.01;
  EXPECT_NE(make_lammps_backend()->not_representable(silodem::load_case(roll)).find("no constant directional rolling torque"),
            std::string::npos);
  EXPECT_EQ(make_liggghts_backend()->not_representable(silodem::load_case(roll)), "");  // rolling_friction cdt
  EXPECT_NE(make_liggghts_backend()->not_representable(silodem::load_case(sliding())).find("no sliding Coulomb law"),
            std::string::npos);
  EXPECT_NE(make_yade_backend()->not_representable(silodem::load_case(roll)).find("rolling"), std::string::npos);
  EXPECT_NE(make_yade_backend()->not_representable(silodem::load_case(sliding())).find("no sliding-only"),
            std::string::npos);
  // Unclamped with a dashpot: YADE always clamps.
  json unclamped = frictional();
  unclamped["contact"].erase("clamp_tensile_force");
  EXPECT_NE(make_yade_backend()->not_representable(silodem::load_case(unclamped)).find("always clamps"),
            std::string::npos);
  // A history spring whose k_t/k_n differs per material: no per-material ks reproduces every pair.
  json ratios = frictional();
  ratios["materials"]["b"]["shear_stiffness_ratio"] = 0.1;
  EXPECT_NE(make_yade_backend()->not_representable(silodem::load_case(ratios)).find("in series"), std::string::npos);
}

/// frictional() with the EPSD rolling spring: mu_r = 0.1, eta_r = 0.3 for both materials.
json epsd(const char* limit) {
  json c = frictional();
  c["contact"]["rolling"] = "epsd";
  c["contact"]["rolling_limit"] = limit;
  for (auto& [name, m] : c["materials"].items()) {
    m["rolling_friction"] = 0.1;
    m["rolling_damping_ratio"] = 0.3;
  }
  return c;
}

/// The three numbers after "rolling sds " on the pair_coeff line of types a, b.
std::vector<double> sds_of(const std::string& deck, const std::string& types) {
  const auto line = deck.find("pair_coeff " + types + " ");
  const auto at = deck.find("rolling sds ", line);
  EXPECT_LT(at, deck.find('\n', line));
  std::istringstream in(deck.substr(at + 12));
  std::vector<double> v(3);
  in >> v[0] >> v[1] >> v[2];
  return v;
}

TEST(LammpsRolling, SdsCarriesTheEpsdSpringDashpotAndLimitPerTypePair) {
  const std::string deck = file(lammps_input(silodem::load_case(epsd("spring_and_dashpot"))), "in.lammps");
  // Ai et al.: k_r = 2.25 k_ij mu_r^2 R*^2 and C_r = 2 eta_r sqrt(I_r k_r), I_r the series of 1.4 m r^2
  // (a wall ball: infinite); LAMMPS's force on the rolling displacement R* theta: k_roll = k_r/R*^2,
  // gamma_roll = C_r/R*^2.
  const double m = 2500 * 4.0 / 3.0 * std::numbers::pi * std::pow(0.005, 3), i_c = 1.4 * m * 0.005 * 0.005;
  const auto expect = [&](const std::string& types, double k_ij, double r_star, double inertia) {
    const auto v = sds_of(deck, types);
    const double k_r = 2.25 * k_ij * 0.01 * r_star * r_star;
    EXPECT_NEAR(v[0], 2.25 * k_ij * 0.01, 1e-9 * v[0]) << types;
    EXPECT_NEAR(v[1], 2 * 0.3 * std::sqrt(inertia * k_r) / (r_star * r_star), 1e-9 * v[1]) << types;
    EXPECT_DOUBLE_EQ(v[2], 0.1) << types;
  };
  expect("1 1", 1e5, 0.0025, i_c / 2);
  expect("1 2", 4e5 / 3, 0.005 * 0.004 / 0.009, i_c);  // the wall ball adds nothing to I_r
}

TEST(LammpsRolling, RefusesWhatSdsCannotHold) {
  // Damped with silodem's default limit (the spring alone): LAMMPS holds spring and dashpot together.
  EXPECT_NE(make_lammps_backend()->not_representable(silodem::load_case(epsd("spring"))).find("spring_and_dashpot"),
            std::string::npos);
  // Undamped, the two limits are one law.
  json undamped = epsd("spring");
  for (auto& [name, m] : undamped["materials"].items()) m["rolling_damping_ratio"] = 0.0;
  EXPECT_EQ(make_lammps_backend()->not_representable(silodem::load_case(undamped)), "");
  // A type with two radii: gamma_roll = C_r/R*^2 is not one number per type pair.
  json two = epsd("spring_and_dashpot");
  two["balls"].push_back({{"id", "m2"}, {"material", "a"}, {"radius", 0.004}, {"position", {0.05, 0, 0.02}}});
  EXPECT_NE(make_lammps_backend()->not_representable(silodem::load_case(two)).find("more than one"), std::string::npos);
}

TEST(LiggghtsRolling, EpsdAndCdtWithTheirMatricesPerTypePair) {
  const auto backend = make_liggghts_backend();
  const auto cfg = silodem::load_case(epsd("spring"));
  ASSERT_EQ(backend->not_representable(cfg), "");
  const auto in = deck_helpers::input_of(*backend, cfg);
  const std::string& deck = file(in, "in.liggghts");
  EXPECT_TRUE(has(deck, "property/global coefficientRollingFriction peratomtypepair 2 0.10000000000000001 "
                        "0.10000000000000001 0.10000000000000001 0.10000000000000001\n"));
  EXPECT_TRUE(has(deck, "property/global coefficientRollingViscousDamping peratomtypepair 2 0.29999999999999999"));
  EXPECT_TRUE(has(deck, "tangential history rolling_friction epsd absolute_damping on"));
  // LIGGGHTS's rolling dashpot reads the wall ball's m r^2: the wall's density is scaled up (1e12).
  EXPECT_TRUE(has(file(in, "data.lmp"), " 7800000000000000 "));
  // LAMMPS's limit with a dashpot has no LIGGGHTS form; Hertz makes epsd's k_n the secant.
  EXPECT_NE(backend->not_representable(silodem::load_case(epsd("spring_and_dashpot"))).find("no LIGGGHTS form"),
            std::string::npos);
  json cdt = frictional();
  cdt["contact"]["rolling"] = "constant_torque";
  for (auto& [name, m] : cdt["materials"].items()) m["rolling_friction"] = 0.1;
  const auto cin = deck_helpers::input_of(*backend, silodem::load_case(cdt));
  EXPECT_TRUE(has(file(cin, "in.liggghts"), "tangential history rolling_friction cdt absolute_damping on"));
  EXPECT_FALSE(has(file(cin, "in.liggghts"), "coefficientRollingViscousDamping"));
}

/// The YADE driver's input (case.json) for a case, with its balls decoded from balls.bin as the
/// driver's read_balls does (columns: tag int64, type int32, fixed uint8, radius, x, v, w).
json yade_case(const json& c) {
  const auto cfg = silodem::load_case(c);
  const auto backend = make_yade_backend();
  EXPECT_EQ(backend->not_representable(cfg), "");
  const auto in = deck_helpers::input_of(*backend, cfg);
  json j = json::parse(file(in, "case.json"));
  const std::string& bin = file(in, "balls.bin");
  const std::size_t n = j["ball_count"].get<std::size_t>();
  EXPECT_EQ(bin.size(), n * 93);
  const auto real = [&](std::size_t at) {
    double x;
    std::memcpy(&x, bin.data() + at, 8);
    return x;
  };
  const auto vec = [&](std::size_t column, std::size_t i) {
    const std::size_t at = n * 21 + column * 24 * n + 24 * i;
    return json::array({real(at), real(at + 8), real(at + 16)});
  };
  j["balls"] = json::array();
  for (std::size_t i = 0; i < n && bin.size() == n * 93; ++i) {
    std::int64_t tag;
    std::int32_t type;
    std::memcpy(&tag, bin.data() + 8 * i, 8);
    std::memcpy(&type, bin.data() + 8 * n + 4 * i, 4);
    j["balls"].push_back({{"tag", tag}, {"type", type}, {"fixed", bin[12 * n + i] != 0}, {"radius", real(13 * n + 8 * i)},
                          {"x", vec(0, i)}, {"v", vec(1, i)}, {"w", vec(2, i)}});
  }
  return j;
}

TEST(YadeFriction, ViscoelasticSpringPerTypeInSeriesWithFrictionPerPair) {
  const json y = yade_case(frictional());
  EXPECT_EQ(y["law"], "viscoelastic");
  EXPECT_TRUE(y["rotation"]);
  // Types: 1 = a (mobile), 2 = b (fixed). YADE's series of ks_i = 0.4 k_i is 0.4 k_ij, of cs_i = 0.25 c_i is 0.25 c_ij.
  ASSERT_EQ(y["types"].size(), 2u);
  EXPECT_DOUBLE_EQ(y["types"][0]["ks"].get<double>(), 0.4 * 2e5);
  EXPECT_DOUBLE_EQ(y["types"][1]["ks"].get<double>(), 0.4 * 4e5);
  EXPECT_DOUBLE_EQ(y["types"][0]["cs"].get<double>(), 0.25 * 6);
  EXPECT_DOUBLE_EQ(y["types"][1]["cs"].get<double>(), 0.25 * 2);
  // Every type pair, with its friction angle: 0.5 between grains, 0.3 grain-wall (material_pairs).
  ASSERT_EQ(y["pairs"].size(), 3u);
  for (const auto& p : y["pairs"]) {
    const double mu = (p["a"] == 1 && p["b"] == 2) ? 0.3 : 0.5;
    EXPECT_DOUBLE_EQ(p["friction_angle"].get<double>(), std::atan(mu)) << p.dump();
  }
  EXPECT_EQ(y["balls"][0]["w"], json::array({0.0, 20.0, 0.0}));
}

TEST(YadeFriction, HertzMindlinDampingRatiosFromTheSolversZeta) {
  json c = frictional();
  c["contact"] = {{"normal", "hertz"}, {"tangential", "mindlin"}, {"clamp_tensile_force", true}};
  c.erase("material_pairs");
  c["materials"] = {{"a", {{"density", 2500}, {"youngs_modulus", 7e10}, {"poisson_ratio", 0.25}, {"restitution", 0.8},
                           {"friction", 0.4}, {"tangential_damping_ratio", 0.5}}},
                    {"b", {{"density", 7800}, {"youngs_modulus", 2e11}, {"poisson_ratio", 0.3}, {"restitution", 0.8},
                           {"friction", 0.4}, {"tangential_damping_ratio", 0.5}}}};
  const json y = yade_case(c);
  EXPECT_EQ(y["law"], "hertz_mindlin");
  EXPECT_EQ(y["types"][1]["young"], 2e11);
  EXPECT_EQ(y["types"][1]["poisson"], 0.3);
  const auto cfg = silodem::load_case(c);
  const auto table = silodem::contact::pair_table(cfg);
  const auto& pp = table.at("a", "b");
  for (const auto& p : y["pairs"]) {
    if (!(p["a"] == 1 && p["b"] == 2)) continue;
    EXPECT_DOUBLE_EQ(p["betan"].get<double>(), pp.hertz_zeta);
    // c_t = 0.5 c_n: 2 betas sqrt(m 8 G* a) = 0.5 * 2 zeta sqrt(m 2 E* a).
    EXPECT_NEAR(p["betas"].get<double>(), 0.5 * pp.hertz_zeta * std::sqrt(pp.e_star / (4.0 * pp.g_star)), 1e-15);
    EXPECT_DOUBLE_EQ(p["friction_angle"].get<double>(), std::atan(0.4));
  }
}

TEST(LiggghtsFriction, HistorySpringMatricesPerTypePair) {
  const auto cfg = silodem::load_case(frictional());
  std::string why;
  const auto backend = make_liggghts_backend();
  EXPECT_EQ(backend->not_representable(cfg), "");
  const auto in = deck_helpers::input_of(*backend, cfg);
  const std::string& deck = file(in, "in.liggghts");
  // kt = 0.4 k_ij; gammat_abs = 0.25 c_ij; mu 0.5 between grains and 0.3 grain–wall (material_pairs).
  EXPECT_TRUE(has(deck, "property/global kt peratomtypepair 2 40000 53333.333333333343 53333.333333333343 80000\n"));
  EXPECT_TRUE(has(deck, "property/global gammat_abs peratomtypepair 2 0.75 0.375 0.375 0.25\n"));
  EXPECT_TRUE(has(deck, "property/global coefficientFriction peratomtypepair 2 0.5 0.29999999999999999 0.29999999999999999 0.5\n"));
  EXPECT_TRUE(has(deck, "hooke/stiffness tangential history absolute_damping on"));
  EXPECT_TRUE(has(deck, "omegax omegay omegaz"));
}

TEST(LammpsFriction, HertzMindlinCarriesTheSolversModuliAndDamping) {
  // Two Hertz materials; LAMMPS's hertz/material makes E* = E/(2(1 - nu^2)) from the pair's E and nu,
  // so the deck gives E = 2 E* with nu = 0; mindlin gets 8 G*; damping tsuji the restitution whose
  // Tsuji polynomial is alpha = 2 zeta sqrt(3/2).
  json c = frictional();
  c["contact"] = {{"normal", "hertz"}, {"tangential", "mindlin"}};
  c.erase("material_pairs");
  c["materials"] = {{"a", {{"density", 2500}, {"youngs_modulus", 7e10}, {"poisson_ratio", 0.25}, {"restitution", 0.8}, {"friction", 0.4}}},
                    {"b", {{"density", 7800}, {"youngs_modulus", 2e11}, {"poisson_ratio", 0.3}, {"restitution", 0.8}, {"friction", 0.4}}}};
  const auto cfg = silodem::load_case(c);
  std::string why;
  const Translation tr = translate(cfg, why);
  const auto& pp = tr.pair(1, 2);
  const double e_star = 1.0 / ((1 - 0.25 * 0.25) / 7e10 + (1 - 0.3 * 0.3) / 2e11);
  const double g_star = 1.0 / (2 * (2 - 0.25) * (1 + 0.25) / 7e10 + 2 * (2 - 0.3) * (1 + 0.3) / 2e11);
  EXPECT_NEAR(pp.e_star / e_star, 1.0, 1e-14);
  EXPECT_NEAR(pp.g_star / g_star, 1.0, 1e-14);
  const std::string deck = file(lammps_input(cfg), "in.lammps");
  const std::string line = deck.substr(deck.find("pair_coeff 1 2 "), deck.find('\n', deck.find("pair_coeff 1 2 ")) - deck.find("pair_coeff 1 2 "));
  std::istringstream in(line);
  std::string w[16];
  for (auto& x : w) in >> x;
  EXPECT_EQ(w[3], "hertz/material");
  EXPECT_NEAR(std::stod(w[4]), 2 * e_star, 1e-6 * e_star);
  const double e = std::stod(w[5]);
  const double alpha = 1.2728 - 4.2783 * e + 11.087 * e * e - 22.348 * std::pow(e, 3) + 27.467 * std::pow(e, 4) -
                       18.022 * std::pow(e, 5) + 4.8218 * std::pow(e, 6);
  EXPECT_NEAR(alpha, 2 * pp.hertz_zeta * std::sqrt(1.5), 1e-12);
  EXPECT_EQ(w[6], "0");
  EXPECT_EQ(w[7], "tangential");
  EXPECT_EQ(w[8], "mindlin");
  EXPECT_NEAR(std::stod(w[9]), 8 * g_star, 1e-6 * g_star);
  EXPECT_EQ(w[11], "0.40000000000000002");
  EXPECT_EQ(w[12], "damping");
  EXPECT_EQ(w[13], "tsuji");
}

TEST(LiggghtsFriction, HertzMindlinPerTypeModuliAndTheRestitutionOfTheSolversZeta) {
  // LIGGGHTS's hertz model damps with 2 sqrt(5/6) (-beta) sqrt(m* S_n), beta = ln e/sqrt(ln^2 e + pi^2):
  // the deck's restitution must give back silodem's zeta; the wall balls' density is scaled so
  // that m* is the mobile ball's, as in silodem.
  json c = frictional();
  c["contact"] = {{"normal", "hertz"}, {"tangential", "mindlin"}, {"clamp_tensile_force", true}};
  c.erase("material_pairs");
  c["materials"] = {{"a", {{"density", 2500}, {"youngs_modulus", 7e10}, {"poisson_ratio", 0.25}, {"restitution", 0.6}, {"friction", 0.4}}},
                    {"b", {{"density", 7800}, {"youngs_modulus", 2e11}, {"poisson_ratio", 0.3}, {"restitution", 0.6}, {"friction", 0.4}}}};
  const auto cfg = silodem::load_case(c);
  std::string why;
  const auto backend = make_liggghts_backend();
  ASSERT_EQ(backend->not_representable(cfg), "");
  const Translation tr = translate(cfg, why);
  const auto in = dynamic_cast<const ReferenceBackend&>(*backend).write_input(cfg, tr);
  const std::string& deck = file(in, "in.liggghts");
  EXPECT_TRUE(has(deck, "property/global youngsModulus peratomtype 70000000000 200000000000\n"));
  EXPECT_TRUE(has(deck, "property/global poissonsRatio peratomtype 0.25 0.29999999999999999\n"));
  EXPECT_TRUE(has(deck, "pair_style gran model hertz tangential history tangential_damping off limitForce on\n"));
  const std::string key = "coefficientRestitution peratomtypepair 2 ";
  std::istringstream row(deck.substr(deck.find(key) + key.size()));
  double e11 = 0;
  row >> e11;
  const double beta = -std::log(e11) / std::sqrt(std::log(e11) * std::log(e11) + std::numbers::pi * std::numbers::pi);
  EXPECT_NEAR(std::sqrt(5.0 / 6.0) * beta, tr.pair(1, 1).hertz_zeta, 1e-12);
  // Wall balls (type 2) 1e12 times denser in the data file; the mobile ball as it is.
  EXPECT_TRUE(has(file(in, "data.lmp"), "2 2 0.0080000000000000002 7800000000000000 0 0 0\n"));
  EXPECT_TRUE(has(file(in, "data.lmp"), "1 1 0.01 2500 0 0 0.02\n"));
  // A Mindlin tangential dashpot has no LIGGGHTS form of its own choosing.
  c["materials"]["a"]["tangential_damping_ratio"] = 0.2;
  c["materials"]["b"]["tangential_damping_ratio"] = 0.2;
  EXPECT_NE(backend->not_representable(silodem::load_case(c)).find("tangential dashpot"), std::string::npos);
  // LIGGGHTS's own (tangential_damping on): gamma_t/gamma_n = sqrt(S_t/S_n) = sqrt(4 G*/E*) for every
  // pair, with E* = 1/sum (1 - nu^2)/E and G* = 1/sum (2 - nu)/G, G = E/(2 (1 + nu)) (Dosta et al. 2024).
  auto own = [](double ea, double na, double eb, double nb) {
    const double e_star = 1.0 / ((1 - na * na) / ea + (1 - nb * nb) / eb);
    const double g_star = 1.0 / ((2 - na) / (ea / (2 * (1 + na))) + (2 - nb) / (eb / (2 * (1 + nb))));
    return std::sqrt(4.0 * g_star / e_star);
  };
  c["materials"]["a"]["tangential_damping_ratio"] = own(7e10, 0.25, 7e10, 0.25);
  c["materials"]["b"]["tangential_damping_ratio"] = own(2e11, 0.3, 2e11, 0.3);
  c["material_pairs"] = json::array({{{"materials", {"a", "b"}}, {"tangential_damping_ratio", own(7e10, 0.25, 2e11, 0.3)}}});
  const auto damped = silodem::load_case(c);
  ASSERT_EQ(backend->not_representable(damped), "");
  const std::string damped_deck = file(dynamic_cast<const ReferenceBackend&>(*backend).write_input(damped, translate(damped, why)),
                                       "in.liggghts");
  EXPECT_TRUE(has(damped_deck, "pair_style gran model hertz tangential history limitForce on\n"));
  // One pair off LIGGGHTS's ratio (its own would be 0.9258 for a-a) is refused.
  c["materials"]["a"]["tangential_damping_ratio"] = 0.9;
  EXPECT_NE(backend->not_representable(silodem::load_case(c)).find("sqrt(4 G*/E*)"), std::string::npos);
}

/// epsd() made undamped (no normal, tangential or rolling dashpot): what YADE's moment law carries.
json undamped_epsd() {
  json c = epsd("spring");
  for (auto& [name, m] : c["materials"].items()) {
    m["damping"] = 0.0;
    m["tangential_damping_ratio"] = 0.0;
    m["rolling_damping_ratio"] = 0.0;
  }
  return c;
}

TEST(YadeRolling, MomentLawConstantsGiveTheSolversSpringsAndLimit) {
  const json y = yade_case(undamped_epsd());
  EXPECT_EQ(y["law"], "moment");
  // YADE's Ip2_CohFrictMat_CohFrictMat_CohFrictPhys, evaluated here on the written materials:
  // k_n = series of 2 E_i R_i, k_s = series of 2 nu_i E_i R_i, k_r = R_1 R_2 k_s H(alphaKr), limit min(etaRoll_i R_i).
  const double r1 = 0.005, r2 = 0.004, r_star = r1 * r2 / (r1 + r2);
  const auto& a = y["types"][0];
  const auto& b = y["types"][1];
  const auto series = [](double x, double z) { return x * z / (x + z); };
  const double ea = a["young"], eb = b["young"], na = a["poisson"], nb = b["poisson"];
  const double aa = a["alpha_kr"], ab = b["alpha_kr"];
  const double k_n = series(2 * ea * r1, 2 * eb * r2), k_s = series(2 * na * ea * r1, 2 * nb * eb * r2);
  const double k_r = r1 * r2 * k_s * 2 * aa * ab / (aa + ab);
  const double limit = std::min(a["eta_roll"].get<double>() * r1, b["eta_roll"].get<double>() * r2);
  const double k_ij = series(2e5, 4e5);
  EXPECT_NEAR(k_n, k_ij, 1e-9 * k_ij);
  EXPECT_NEAR(k_s, 0.4 * k_ij, 1e-9 * k_ij);
  EXPECT_NEAR(k_r, 2.25 * k_ij * 0.1 * 0.1 * r_star * r_star, 1e-9 * k_r);  // Ai et al. (2011)
  EXPECT_NEAR(limit, 0.1 * r_star, 1e-12 * limit);
  for (const auto& p : y["pairs"]) {
    if (!(p["a"] == 1 && p["b"] == 2)) continue;
    EXPECT_DOUBLE_EQ(p["friction_angle"].get<double>(), std::atan(0.3));
  }
}

TEST(YadeRolling, RefusesDashpotsAndPairsNoPerMaterialValuesReproduce) {
  const auto backend = make_yade_backend();
  EXPECT_NE(backend->not_representable(silodem::load_case(epsd("spring"))).find("has no dashpot"), std::string::npos);
  // A second grain: the grain pair wants the limit mu_r r/2 and the grain-wall pair mu_r R*. With the
  // wall ball smaller than the grains (R* < r/2) min(etaRoll_i R_i) gives both; with a larger one it cannot.
  json two = undamped_epsd();
  two["balls"].push_back({{"id", "m2"}, {"material", "a"}, {"radius", 0.005}, {"position", {0.05, 0, 0.02}}});
  EXPECT_EQ(backend->not_representable(silodem::load_case(two)), "");
  two["balls"][1]["radius"] = 0.05;
  two["balls"][1]["position"] = {0, 0, -0.05};
  EXPECT_NE(backend->not_representable(silodem::load_case(two)).find("no per-material values reproduce"), std::string::npos);
  // Two radii in one material: E_i = k_i/(2 R_i) is not one number.
  json radii = undamped_epsd();
  radii["balls"].push_back({{"id", "m2"}, {"material", "a"}, {"radius", 0.004}, {"position", {0.05, 0, 0.02}}});
  EXPECT_NE(backend->not_representable(silodem::load_case(radii)).find("one radius per"), std::string::npos);
}
