// The drop feeder's release placement (the shared fill sequence of comparison (a)): each drop
// appears at its release point with the release velocity on its own step, whatever the fill, the
// sequence announced beforehand is the one placed, and a release point inside a ball is refused.
#include <gtest/gtest.h>

#include "silodem/fill/drop_feeder.hpp"

using namespace silodem;

namespace {

DropSpec release_spec() {
  DropSpec d;
  d.material = "g";
  d.r_min = 0.002;
  d.r_max = 0.003;
  d.z0 = 0.1;
  d.count = 3;
  d.x_min = -0.01, d.x_max = 0.01, d.y_min = -0.01, d.y_max = 0.01;
  d.interval_steps = 10;
  d.release = true;
  d.release_speed = 0.5;
  return d;
}

Material grain() {
  Material m;
  m.name = "g";
  m.density = 2500.0;
  m.k = 1e5;
  m.c = 1.0;
  return m;
}

}  // namespace

TEST(DropFeederRelease, EachDropAtItsPointOnItsStepAsAnnounced) {
  const DropSpec spec = release_spec();
  DropFeeder feeder(spec, grain(), 0, Vec3(0, 0, -9.81), 42, 101);
  const std::vector<DropRecord> plan = feeder.planned_releases();
  ASSERT_EQ(plan.size(), 3u);
  Particles p;
  // A mobile ball above the release height: first-contact drops would wait; released ones do not.
  p.add({Vec3(0.5, 0.5, 0.2), Vec3::Zero(), 0.002, 1e-4, 1e5, 1.0, 0, "high", 1}, false);
  std::vector<long> steps;
  for (long step = 0; step < 40; ++step)
    if (auto rec = feeder.maybe_drop(p, step, 1e-3 * double(step))) {
      ASSERT_EQ(rec->outcome, "placed");
      const DropRecord& want = plan[steps.size()];
      EXPECT_EQ(rec->index, want.index);
      EXPECT_EQ(rec->start, want.start);
      EXPECT_EQ(rec->r, want.r);
      const std::size_t i = std::size_t(p.find("drop" + std::to_string(rec->index)));
      EXPECT_EQ(p.x[i], Vec3(want.start.x(), want.start.y(), 0.1));
      EXPECT_EQ(p.v[i], Vec3(0.0, 0.0, -0.5));
      EXPECT_EQ(p.tag[i], 101 + rec->index);
      EXPECT_NEAR(p.m[i], 2500.0 * 4.0 / 3.0 * kPi * rec->r * rec->r * rec->r, 1e-15);  // (1): 4/3, docs/model.md §1
      EXPECT_GE(rec->r, 0.002);
      EXPECT_LE(rec->r, 0.003);
      EXPECT_GE(rec->start.x(), -0.01);
      EXPECT_LE(rec->start.x(), 0.01);
      steps.push_back(step);
    }
  EXPECT_EQ(steps, (std::vector<long>{0, 10, 20}));
  EXPECT_TRUE(feeder.done());
  EXPECT_EQ(feeder.placed(), 3);
  // Distinct draws: the points are not all one point.
  EXPECT_NE(plan[0].start, plan[1].start);
}

TEST(DropFeederRelease, APointInsideABallIsRefusedAndUsesUpItsIndex) {
  DropSpec spec = release_spec();
  spec.positions = {{0.0, 0.0}, {0.05, 0.0}};
  spec.count = 2;
  spec.interval_steps = 1;
  DropFeeder feeder(spec, grain(), 0, Vec3(0, 0, -9.81), 1, 1);
  Particles p;
  p.add({Vec3(0.0, 0.0, 0.103), Vec3::Zero(), 0.002, 1e-4, 1e5, 1.0, 0, "in_the_way", 1}, true);
  const auto first = feeder.maybe_drop(p, 0, 0.0);
  ASSERT_TRUE(first);
  EXPECT_EQ(first->outcome, "start_overlaps");  // 3 mm apart, radii sum at least 4 mm
  EXPECT_EQ(first->obstacle_id, "in_the_way");
  EXPECT_EQ(p.size(), 1u);
  const auto second = feeder.maybe_drop(p, 1, 0.0);
  ASSERT_TRUE(second);
  EXPECT_EQ(second->outcome, "placed");
  EXPECT_EQ(second->index, 1);
  EXPECT_EQ(feeder.rejected(), 1);
}
