// The translation every reference code receives, and each backend's generated input: the right
// stiffness, damping, radii, time step, fixed groups and clamp switch for a known case.
#include <cstring>
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "deck_helpers.hpp"
#include "harness/backends/reference_backend.hpp"
#include "harness/backends/translation.hpp"
#include "silodem/case/case_loader.hpp"

using namespace harness;
using nlohmann::json;

namespace {

json two_materials() {
  // A mobile ball of material "a" on a fixed ball of material "b", gravity on.
  return json::parse(R"({
    "name": "deck",
    "materials": {"a": {"density": 2500, "stiffness": 2e5, "damping": 6},
                  "b": {"density": 7800, "stiffness": 4e5, "damping": 2}},
    "balls": [{"id": "m", "material": "a", "radius": 0.005, "position": [0, 0, 0.02], "velocity": [0, 0, -0.1]},
              {"id": "w", "material": "b", "radius": 0.004, "position": [0, 0, 0], "fixed": true}],
    "integrator": {"scheme": "velocity_verlet", "dashpot_velocity": "half_step"},
    "time": {"dt": 2e-6, "duration": 1e-3},
    "output": {"dump_interval_steps": 5}
  })");
}

using deck_helpers::file;
using deck_helpers::has;

}  // namespace

TEST(Translation, TypesTagsAndSeriesConstants) {
  std::string why;
  const Translation t = translate(silodem::load_case(two_materials()), why);
  ASSERT_EQ(why, "");
  ASSERT_EQ(t.balls.size(), 2u);
  EXPECT_EQ(t.balls[0].tag, 1);
  EXPECT_EQ(t.balls[1].tag, 2);
  EXPECT_TRUE(t.balls[1].fixed);
  ASSERT_EQ(t.types.size(), 2u);
  EXPECT_NEAR(t.pair_k(1, 2), 2e5 * 4e5 / 6e5, 1e-6);  // (11)
  EXPECT_NEAR(t.pair_c(1, 2), 6.0 * 2.0 / 8.0, 1e-12);
  EXPECT_EQ(t.steps, 500);
  EXPECT_NEAR(t.skin, 0.2 * 0.004, 1e-15);
}

TEST(Translation, SingleDropIsPlacedLikeTheSolverAndTimedDropsAreRefused) {
  json c = two_materials();
  c["drops"] = {{"material", "a"}, {"radius", {0.003, 0.003}}, {"z0", 0.1}, {"count", 1}, {"positions", {{0.0, 0.0}}}};
  c["balls"].erase(0);
  c["balls"].push_back({{"id", "m"}, {"material", "a"}, {"radius", 0.005}, {"position", {1, 0, 0}}});
  std::string why;
  Translation t = translate(silodem::load_case(c), why);
  ASSERT_EQ(why, "");
  ASSERT_EQ(t.drops.size(), 1u);
  const auto& d = t.balls.back();
  EXPECT_EQ(d.id, "drop0");
  EXPECT_NEAR(d.x.z(), 0.007, 1e-15);  // touches the fixed ball: 0.004 + 0.003 above its centre
  EXPECT_NEAR(d.v.z(), -std::sqrt(2 * 9.81 * (0.1 - 0.007)), 1e-12);
  c["drops"]["count"] = 2;
  c["drops"]["positions"] = {{0.0, 0.0}, {0.001, 0.0}};
  translate(silodem::load_case(c), why);
  EXPECT_NE(why.find("timed analytic drops"), std::string::npos);
}

TEST(Translation, ReleasedDropsBecomeInsertEventsInEveryCode) {
  json c = two_materials();
  c["drops"] = {{"material", "a"}, {"radius", {0.003, 0.003}}, {"z0", 0.1}, {"count", 3}, {"interval_steps", 200},
                {"positions", {{0.0, 0.0}, {0.01, 0.0}, {0.0, 0.01}}}, {"placement", "release"},
                {"release_speed", 0.5}};
  const auto cfg = silodem::load_case(c);
  std::string why;
  const Translation t = translate(cfg, why);
  ASSERT_EQ(why, "");
  ASSERT_EQ(t.events.size(), 3u);  // steps 0, 200, 400 of the 500
  for (std::size_t k = 0; k < 3; ++k) {
    const TranslatedEvent& ev = t.events[k];
    EXPECT_EQ(ev.type, "insert");
    EXPECT_EQ(ev.step, long(200 * k));
    EXPECT_EQ(ev.ball.tag, 3 + long(k));  // after the two listed balls, as the solver tags drops
    EXPECT_EQ(ev.ball.id, "drop" + std::to_string(k));
    EXPECT_EQ(ev.ball.radius, 0.003);
    EXPECT_NEAR(ev.ball.mass, 2500.0 * 4.0 / 3.0 * M_PI * 0.003 * 0.003 * 0.003, 1e-15);
    EXPECT_EQ(ev.ball.x, silodem::Vec3(k == 1 ? 0.01 : 0.0, k == 2 ? 0.01 : 0.0, 0.1));
    EXPECT_EQ(ev.ball.v, silodem::Vec3(0.0, 0.0, -0.5));
  }
  const auto lmp = make_lammps_backend();
  const auto in = dynamic_cast<const ReferenceBackend&>(*lmp).write_input(cfg, t);
  const std::string& deck = file(in, "in.lammps");
  EXPECT_TRUE(has(deck, "run 200\ncreate_atoms 1 single 0.01 0 0.10000000000000001 units box\nset atom 4 diameter "
                        "0.0060000000000000001 density 2500 vx 0 vy 0 vz -0.5\ngroup mobile id 4\nrun 200\n"));
  EXPECT_TRUE(has(deck, "run 100\n"));  // the rest after the last insert
  // The box (shrink-wrapped, with the data file's box as its minimum) holds the release points.
  const std::string& data = file(in, "data.lmp");
  const std::size_t z_line = data.rfind('\n', data.find(" zlo zhi")) + 1;
  double zlo = 0.0, zhi = 0.0;
  ASSERT_EQ(std::sscanf(data.c_str() + z_line, "%lf %lf", &zlo, &zhi), 2);
  EXPECT_GE(zhi, 0.1 + 0.003);  // the listed balls alone reach 0.02 + pad
  const auto yade = make_yade_backend();
  json c2 = c;
  c2["contact"] = {{"clamp_tensile_force", true}};
  const auto cfg2 = silodem::load_case(c2);
  const json j = json::parse(file(dynamic_cast<const ReferenceBackend&>(*yade).write_input(cfg2, translate(cfg2, why)), "case.json"));
  ASSERT_EQ(j["events"].size(), 3u);
  EXPECT_EQ(j["events"][2]["type"], "insert");
  EXPECT_EQ(j["events"][2]["step"], 400);
  EXPECT_EQ(j["events"][2]["ball"]["tag"], 5);
  EXPECT_EQ(j["events"][2]["ball"]["v"][2], -0.5);
  // With outflow the created tags would part from the solver's: refused with the reason.
  json out = c;
  out["stages"] = {{"outflow", {{"below_z", -1.0}, {"mode", "remove"}, {"every_steps", 10}}}};
  translate(silodem::load_case(out), why);
  EXPECT_NE(why.find("largest tag"), std::string::npos);
}

TEST(LammpsDeck, CarriesTheCaseNumbers) {
  const auto cfg = silodem::load_case(two_materials());
  std::string why;
  const auto backend = make_lammps_backend();
  const auto& lmp = dynamic_cast<const ReferenceBackend&>(*backend);
  const auto in = lmp.write_input(cfg, translate(cfg, why));
  const std::string& deck = file(in, "in.lammps");
  EXPECT_TRUE(has(deck, "pair_coeff 1 2 hooke 133333.33333333334 1.5 tangential linear_nohistory 0 0 damping velocity\n"));
  EXPECT_TRUE(has(deck, "pair_coeff 1 1 hooke 100000 3 "));
  EXPECT_TRUE(has(deck, "timestep 1.9999999999999999e-06"));
  EXPECT_TRUE(has(deck, "group wall type 2"));
  EXPECT_TRUE(has(deck, "exclude type 2 2"));
  EXPECT_TRUE(has(deck, "fix grav mobile gravity 9.8100000000000005 vector 0 0 -1"));
  EXPECT_TRUE(has(deck, "fix integrate mobile nve/sphere"));
  EXPECT_TRUE(has(deck, "dump d all custom 5 dump.txt id mass radius x y z vx vy vz fx fy fz"));
  EXPECT_TRUE(has(deck, "run 500"));
  EXPECT_FALSE(has(deck, "limit_damping"));
  const std::string& data = file(in, "data.lmp");
  EXPECT_TRUE(has(data, "1 1 0.01 2500 0 0 0.02"));  // id type diameter density x y z
  EXPECT_TRUE(has(data, "2 2 0.0080000000000000002 7800 0 0 0"));
  EXPECT_TRUE(has(data, "1 0 0 -0.10000000000000001 0 0 0"));  // velocities
  json c = two_materials();
  c["contact"] = {{"clamp_tensile_force", true}};
  const auto clamped = silodem::load_case(c);
  EXPECT_TRUE(has(file(lmp.write_input(clamped, translate(clamped, why)), "in.lammps"), "damping velocity limit_damping"));
}

TEST(LiggghtsDeck, FullTypePairMatricesAndClamp) {
  json c = two_materials();
  c["contact"] = {{"clamp_tensile_force", true}};
  const auto cfg = silodem::load_case(c);
  std::string why;
  const auto backend = make_liggghts_backend();
  const auto in = deck_helpers::input_of(*backend, cfg);
  const std::string& deck = file(in, "in.liggghts");
  EXPECT_TRUE(has(deck, "property/global kn peratomtypepair 2 100000 133333.33333333334 133333.33333333334 200000\n"));
  EXPECT_TRUE(has(deck, "property/global gamman_abs peratomtypepair 2 3 1.5 1.5 1\n"));
  EXPECT_TRUE(has(deck, "property/global coefficientFriction peratomtypepair 2 0 0 0 0\n"));
  EXPECT_TRUE(has(deck, "absolute_damping on limitForce on"));
  EXPECT_TRUE(has(deck, "exclude type 2 2"));
}

TEST(YadeInput, PerTypeConstantsAndRepresentability) {
  json c = two_materials();
  c["contact"] = {{"clamp_tensile_force", true}};
  const auto cfg = silodem::load_case(c);
  std::string why;
  const auto backend = make_yade_backend();
  const auto in = deck_helpers::input_of(*backend, cfg);
  const json j = json::parse(file(in, "case.json"));
  EXPECT_EQ(j["types"][0]["k"], 2e5);  // per-ball: YADE makes the series itself
  EXPECT_EQ(j["types"][1]["c"], 2.0);
  // The balls as columns (tag, type, fixed, radius, x, v, w), read back as the driver does.
  const std::string& bin = file(in, "balls.bin");
  const std::size_t n = j["ball_count"].get<std::size_t>();
  ASSERT_EQ(n, cfg.balls.size());
  ASSERT_EQ(bin.size(), n * (8 + 4 + 1 + 8 + 72));
  EXPECT_EQ(bin[n * 12 + 1], 1);  // ball 1 is the fixed one
  double radius = 0.0, x1[3];
  std::memcpy(&radius, bin.data() + n * 13, 8);
  std::memcpy(x1, bin.data() + n * 21 + 24, 24);
  EXPECT_EQ(radius, cfg.balls[0].radius);
  EXPECT_EQ(silodem::Vec3(x1[0], x1[1], x1[2]), cfg.balls[1].position);
  EXPECT_EQ(j["dump_interval"], 5);
  EXPECT_EQ(backend->not_representable(cfg), "");
  EXPECT_NE(backend->not_representable(silodem::load_case(two_materials())).find("always clamps"), std::string::npos);
}

TEST(Representability, ReasonsAreGiven) {
  const auto lmp = make_lammps_backend();
  json pc = two_materials();
  pc["integrator"] = {{"scheme", "predictor_corrector"}};
  EXPECT_NE(lmp->not_representable(silodem::load_case(pc)).find("half-step velocity"), std::string::npos);
  json coh = two_materials();
  coh["contact"] = {{"cohesion", {{"enabled", true}}}};
  EXPECT_NE(lmp->not_representable(silodem::load_case(coh)).find("tensile spring"), std::string::npos);
}

TEST(ReferenceRun, TimeOutIsARecordedErrorWithTheLogTail) {
  // A 10^7-step LAMMPS run (several seconds even for two balls) given 1 s: the backend must stop it
  // and record why.
  json c = two_materials();
  c["time"]["duration"] = 20.0;
  c["output"]["dump_interval_steps"] = 1000000;
  const auto cfg = silodem::load_case(c);
  const auto backend = make_lammps_backend();
  if (!backend->missing().empty()) GTEST_FAIL() << backend->missing();
  const auto dir = std::filesystem::temp_directory_path() / "silodem_timeout";
  const BackendResult r = backend->run(cfg, dir, 1.0);
  EXPECT_EQ(r.status, BackendResult::Status::Failed);
  EXPECT_NE(r.reason.find("timed out after 1 s"), std::string::npos) << r.reason;
  std::ifstream in(dir / "summary.json");
  const json s = json::parse(in);
  EXPECT_EQ(s["status"], "failed");
  EXPECT_EQ(s["code"], "lammps");
  EXPECT_TRUE(has(s["input"].get<std::string>(), "pair_style granular"));
  EXPECT_EQ(s["run"]["exit_status"], 124);
}

TEST(Translation, LeaversAreDeletedOnTheCasesIntervalInEveryCode) {
  json c = two_materials();
  c["contact"] = {{"clamp_tensile_force", true}};
  c["stages"] = {{"outflow", {{"below_z", -0.01}, {"mode", "remove"}, {"every_steps", 150}}}};
  const auto cfg = silodem::load_case(c);
  std::string why;
  const Translation tr = translate(cfg, why);
  EXPECT_EQ(why, "");
  EXPECT_EQ(tr.outflow_every_steps, 150);
  const auto lmp = make_lammps_backend(), lig = make_liggghts_backend(), yade = make_yade_backend();
  EXPECT_TRUE(has(file(dynamic_cast<const ReferenceBackend&>(*lmp).write_input(cfg, tr), "in.lammps"),
                  "fix outflow mobile evaporate 150 "));
  EXPECT_TRUE(has(file(dynamic_cast<const ReferenceBackend&>(*lig).write_input(cfg, tr), "in.liggghts"),
                  "run 500 every 150 \"delete_atoms region outflow compress no\""));
  EXPECT_EQ(json::parse(file(dynamic_cast<const ReferenceBackend&>(*yade).write_input(cfg, tr), "case.json"))["outflow_every_steps"], 150);
  // Every step (silodem's default) is refused with the reason: it would cost the reference codes 10x.
  c["stages"]["outflow"].erase("every_steps");
  const auto every = silodem::load_case(c);
  translate(every, why);
  EXPECT_NE(why.find("every_steps = 1"), std::string::npos) << why;
}

TEST(Translation, MovingWallsBecomeFixMoveAndYadesFixedBodyVelocity) {
  // The fixed ball set moving at t = 0 and stopped at step 250: one group and fix in LAMMPS and
  // LIGGGHTS (replaced, then the velocity zeroed), the velocity of its body in YADE's events.
  json c = two_materials();
  c["contact"] = {{"clamp_tensile_force", true}};
  c["stages"] = {{"events",
                  {{{"time", 0}, {"type", "move_wall"}, {"ball", "w"}, {"velocity", {0, 0, 0.25}}},
                   {{"time", 5e-4}, {"type", "move_wall"}, {"ball", "w"}, {"velocity", {0, 0, 0}}}}}};
  const auto cfg = silodem::load_case(c);
  std::string why;
  const Translation tr = translate(cfg, why);
  ASSERT_EQ(why, "");
  ASSERT_EQ(tr.events.size(), 2u);
  EXPECT_EQ(tr.events[0].step, 0);
  EXPECT_EQ(tr.events[1].step, 250);
  EXPECT_EQ(tr.events[0].tags, std::vector<std::int64_t>{2});
  EXPECT_FALSE(tr.events[0].moved_before);
  EXPECT_TRUE(tr.events[1].moved_before);
  for (const auto& backend : {make_lammps_backend(), make_liggghts_backend()}) {
    const auto in = dynamic_cast<const ReferenceBackend&>(*backend).write_input(cfg, tr);
    const std::string deck = file(in, backend->code() == "lammps" ? "in.lammps" : "in.liggghts");
    EXPECT_TRUE(has(deck, "group wall_w id 2\nfix wall_w wall_w move linear 0 0 0.25\n")) << deck;
    EXPECT_TRUE(has(deck, "unfix wall_w\nvelocity wall_w set 0 0 0\n")) << deck;
    EXPECT_LT(deck.find("move linear"), deck.find("unfix wall_w"));
  }
  const json y = json::parse(file(dynamic_cast<const ReferenceBackend&>(*make_yade_backend()).write_input(cfg, tr), "case.json"));
  EXPECT_EQ(y["events"][0]["type"], "move_wall");
  EXPECT_EQ(y["events"][0]["velocity"], json::array({0.0, 0.0, 0.25}));
  EXPECT_EQ(y["events"][1]["velocity"], json::array({0.0, 0.0, 0.0}));
  // A continuation from step 100 (a state exported mid-motion) finds the wall moving: its velocity
  // is set again at the start, then stopped at step 250; from step 300 it is stopped already.
  auto later = cfg;
  later.start_step = 100;
  const Translation mid = translate(later, why);
  ASSERT_EQ(mid.events.size(), 2u);
  EXPECT_EQ(mid.events[0].step, 100);
  EXPECT_EQ(mid.events[0].velocity.z(), 0.25);
  EXPECT_FALSE(mid.events[0].moved_before);
  EXPECT_TRUE(mid.events[1].moved_before);
  later.start_step = 300;
  const Translation after = translate(later, why);
  ASSERT_EQ(after.events.size(), 1u);
  EXPECT_EQ(after.events[0].step, 300);
  EXPECT_TRUE(after.events[0].velocity.isZero());
}
