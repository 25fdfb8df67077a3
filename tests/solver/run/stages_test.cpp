// Stage changes: opening the outlet, discharge with recycling or removal, sudden closure — mass
// conserved, no ball lost or duplicated, ids and tags stable, the ledger told about every change.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "silodem/run/stages.hpp"

using namespace silodem;

namespace {

Particles scene() {
  Particles p;
  std::int64_t tag = 0;
  for (int i = 0; i < 5; ++i) p.add({Vec3(0, 0, 0.1 * i), Vec3(0, 0, -1), 0.005, 1.0 + i, 1, 0, 0, "g" + std::to_string(i), ++tag}, false);
  for (int i = 0; i < 4; ++i) p.add({Vec3(0.01 * i, 0, -0.02), Vec3::Zero(), 0.005, 10.0, 1, 0, 0, "gate_" + std::to_string(i), ++tag}, true);
  for (int i = 0; i < 3; ++i) p.add({Vec3(0.1, 0, 0.1 * i), Vec3::Zero(), 0.005, 20.0, 1, 0, 0, "wall_" + std::to_string(i), ++tag}, true);
  return p;
}

std::map<std::string, std::int64_t> tags(const Particles& p) {
  std::map<std::string, std::int64_t> t;
  for (std::size_t i = 0; i < p.size(); ++i) t[p.id[i]] = p.tag[i];
  return t;
}

double mass(const Particles& p, bool mobile) {
  double m = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) m += (p.fixed(i) != mobile) ? p.m[i] : 0.0;
  return m;
}

}  // namespace

TEST(Particles, ConversionsKeepEveryBallAndItsIdentity) {
  Particles p = scene();
  const auto before = tags(p);
  const std::size_t j = p.make_fixed(std::size_t(p.find("g2")));
  EXPECT_TRUE(p.fixed(j));
  EXPECT_EQ(p.id[j], "g2");
  EXPECT_EQ(p.v[j], Vec3::Zero());
  const std::size_t k = p.make_mobile(std::size_t(p.find("wall_1")));
  EXPECT_FALSE(p.fixed(k));
  EXPECT_EQ(tags(p), before);  // same balls, same tags
  EXPECT_EQ(p.n_mobile, 5u);
  p.remove_mobile(std::size_t(p.find("g4")));
  EXPECT_EQ(p.find("g4"), -1);
  EXPECT_EQ(p.size(), 11u);
  auto after = before;
  after.erase("g4");
  EXPECT_EQ(tags(p), after);
  for (std::size_t i = 0; i < p.n_mobile; ++i) EXPECT_FALSE(p.fixed(i));
}

TEST(Stages, OpenDischargeRecycleAndClose) {
  CaseConfig cfg;
  cfg.gravity = Vec3(0, 0, -10);
  StageEvent open, close;
  open.time = 0.5;
  open.type = "open_outlet";
  open.wall = "gate";
  open.release_mobile = true;  // the paper's words: the gate balls start moving
  close.time = 1.0;
  close.type = "close_outlet";
  close.centre = Vec3(0, 0, 0.1);
  close.diameter = close.thickness = 0.02;
  cfg.events = {open, close};
  cfg.outflow = {true, 0.05, true};
  DropSpec d;
  d.r_min = d.r_max = 0.005;
  d.z0 = 1.0;
  d.count = 0;
  d.x_min = d.x_max = d.y_min = d.y_max = 0.0;
  DropFeeder feeder(d, Material{"m", 1000, 1, 0, ""}, 0, cfg.gravity, 1, 100);
  EnergyLedger ledger(cfg.gravity);
  Particles p = scene();
  StageController st(cfg, ledger);
  const double m_total = mass(p, true) + mass(p, false);
  // t = 0: g0 (z = 0) is below the outflow height 0.05: it leaves and waits to be recycled.
  EXPECT_TRUE(st.apply(p, 0, 0.0, &feeder));
  auto exits = st.take_exits();
  ASSERT_EQ(exits.size(), 1u);
  EXPECT_EQ(exits[0].id, "g0");
  EXPECT_EQ(feeder.waiting(), 1u);
  EXPECT_NEAR(ledger.state().withdrawn, 0.5 * 1.0 * 1.0 + 0.0, 1e-12);  // ½ m v², at z = 0
  // t = 0.5: the four gate balls start moving — and, lying below the outflow height in this bare
  // scene, leave in the same pass.
  EXPECT_TRUE(st.apply(p, 500, 0.5, &feeder));
  EXPECT_NEAR(ledger.state().injected, 4 * 10.0 * 10.0 * -0.02, 1e-12);  // at rest: m g z each
  EXPECT_EQ(st.take_exits().size(), 4u);
  EXPECT_EQ(feeder.waiting(), 5u);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(p.find("gate_" + std::to_string(i)), -1);
  // The recycled ball comes back at the top with its id, tag and mass.
  const auto rec = feeder.maybe_drop(p, 0, 0.7);
  ASSERT_TRUE(rec);
  EXPECT_EQ(rec->outcome, "placed");  // lands on g3, the highest ball under the inlet
  EXPECT_EQ(rec->recycled_id, "g0");
  const std::size_t g0 = std::size_t(p.find("g0"));
  EXPECT_EQ(p.tag[g0], 1);
  EXPECT_EQ(p.m[g0], 1.0);
  EXPECT_EQ(feeder.waiting(), 4u);
  // t = 1: g1 sits in the closure slab (z = 0.1): it is stopped and fixed.
  EXPECT_TRUE(st.apply(p, 1000, 1.0, &feeder));
  const std::size_t g1 = std::size_t(p.find("g1"));
  EXPECT_TRUE(p.fixed(g1));
  EXPECT_EQ(p.v[g1], Vec3::Zero());
  EXPECT_EQ(st.converted(), 1u);
  // Mass: what is in the scene plus what waits to be recycled is what there was.
  const double waiting = 4 * 10.0;  // the four gate balls
  EXPECT_NEAR(mass(p, true) + mass(p, false) + waiting, m_total, 1e-12);
  std::set<std::string> ids(p.id.begin(), p.id.end());
  EXPECT_EQ(ids.size(), p.size());  // no duplicates
}

TEST(Stages, OpeningCanTakeTheGateAway) {
  CaseConfig cfg;
  StageEvent open;
  open.type = "open_outlet";
  open.wall = "gate";
  cfg.events = {open};
  EnergyLedger ledger(Vec3(0, 0, -10));
  Particles p = scene();
  StageController st(cfg, ledger);
  EXPECT_TRUE(st.apply(p, 0, 0.0, nullptr));
  EXPECT_EQ(p.size(), 8u);  // 5 grains + 3 wall balls: the 4 gate balls are gone
  for (int i = 0; i < 4; ++i) EXPECT_EQ(p.find("gate_" + std::to_string(i)), -1);
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(p.fixed(std::size_t(p.find("wall_" + std::to_string(i)))));
  EXPECT_EQ(ledger.state().injected, 0.0);
}

TEST(Stages, LeaversAreLookedForEveryEveryStepsOnly) {
  // stages.outflow.every_steps = 200, as the reference codes delete leavers: g0 lies below the
  // outflow height from the start but leaves only at the top of a step that is a multiple of 200.
  CaseConfig cfg;
  cfg.outflow = {true, 0.05, false, 200};
  EnergyLedger ledger(Vec3(0, 0, -10));
  Particles p = scene();
  StageController st(cfg, ledger);
  for (long step : {1L, 199L, 201L, 399L}) {
    EXPECT_FALSE(st.apply(p, step, 1e-4 * double(step), nullptr)) << step;
    EXPECT_TRUE(st.take_exits().empty()) << step;
  }
  EXPECT_NE(p.find("g0"), -1);
  EXPECT_TRUE(st.apply(p, 400, 0.04, nullptr));
  const auto exits = st.take_exits();
  ASSERT_FALSE(exits.empty());
  EXPECT_EQ(exits[0].id, "g0");
  EXPECT_EQ(p.find("g0"), -1);
}

TEST(Stages, MoveWallSetsItsBallsMovingAndAContinuationFindsThemMoving) {
  CaseConfig cfg;
  cfg.dt = 1e-3;
  StageEvent go, stop;
  go.type = stop.type = "move_wall";
  go.wall = stop.wall = "wall";
  go.velocity = Vec3(0, 0, 0.5);
  stop.time = 1.0;
  cfg.events = {go, stop};
  EnergyLedger ledger(Vec3(0, 0, -10));
  Particles p = scene();
  StageController st(cfg, ledger);
  EXPECT_TRUE(st.apply(p, 0, 0.0, nullptr));
  EXPECT_TRUE(p.moving_walls);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(p.v[std::size_t(p.find("wall_" + std::to_string(i)))], Vec3(0, 0, 0.5));
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(p.v[std::size_t(p.find("gate_" + std::to_string(i)))].isZero());
  // A continuation from step 500 (t = 0.5 s): the first event ran before it, its velocity is set again.
  cfg.start_step = 500;
  Particles q = scene();
  StageController later(cfg, ledger);
  EXPECT_TRUE(later.apply(q, 500, 0.5, nullptr));
  EXPECT_EQ(q.v[std::size_t(q.find("wall_0"))], Vec3(0, 0, 0.5));
  EXPECT_TRUE(later.apply(q, 1000, 1.0, nullptr));  // stopped
  EXPECT_TRUE(q.v[std::size_t(q.find("wall_0"))].isZero());
  EXPECT_FALSE(q.moving_walls);
}
