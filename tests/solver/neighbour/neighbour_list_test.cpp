// The cell-grid Verlet list against the all-pairs oracle, for polydisperse mobile and wall balls.
#include <gtest/gtest.h>

#include <set>

#include "silodem/core/parallel.hpp"
#include "silodem/core/random.hpp"
#include "silodem/neighbour/all_pairs.hpp"
#include "silodem/neighbour/neighbour_list.hpp"

using namespace silodem;

namespace {

Particles random_scene(std::uint64_t seed, int mobile, int wall) {
  Random rng(seed);
  Particles p;
  for (int i = 0; i < mobile + wall; ++i) {
    const double r = rng.uniform(0.002, 0.006);  // polydisperse: 3x spread of radii
    const Vec3 x(rng.uniform(0, 0.1), rng.uniform(0, 0.1), rng.uniform(0, 0.1));
    p.add({x, Vec3::Zero(), r, 1.0, 1.0, 0.0, 0, ""}, i >= mobile);
  }
  return p;
}

std::set<std::pair<std::size_t, std::size_t>> listed(const NeighbourList& nl, const Particles& p) {
  std::set<std::pair<std::size_t, std::size_t>> s;
  for (std::size_t i = 0; i < p.n_mobile; ++i)
    for (std::size_t k = nl.begin(i); k < nl.end(i); ++k) s.emplace(std::min<std::size_t>(i, nl.neighbour(k)), std::max<std::size_t>(i, nl.neighbour(k)));
  return s;
}

}  // namespace

TEST(NeighbourList, EqualsAllPairsWithinReachPlusSkinAtBuild) {
  Particles p = random_scene(7, 600, 300);
  const double skin = 0.001, reach = 0.0005;
  NeighbourList nl(skin, reach);
  nl.build(p);
  const auto got = listed(nl, p);
  const auto want = all_pairs_within(p, reach + skin);
  const std::set<std::pair<std::size_t, std::size_t>> want_set(want.begin(), want.end());
  EXPECT_EQ(got, want_set);
  EXPECT_EQ(got.size(), nl.pair_count());  // each pair once
  for (const auto& [i, j] : got) EXPECT_FALSE(p.fixed(i) && p.fixed(j)) << "wall-wall pair listed";
  // The owner of a slot is the ball it is stored under (the force loop walks slots flat).
  for (std::size_t i = 0; i < p.n_mobile; ++i)
    for (std::size_t s = nl.begin(i); s < nl.end(i); ++s) ASSERT_EQ(nl.owner(s), i);
}

TEST(NeighbourList, FrontIsTheLargestIndexGapOfAMobilePairInTheOracle) {
  Particles p = random_scene(13, 700, 250);
  const double skin = 0.001;
  NeighbourList nl(skin, 0.0);
  nl.build(p);
  std::size_t want = 0;
  for (const auto& [i, j] : all_pairs_within(p, skin))
    if (j < p.n_mobile) want = std::max(want, j - i);  // pairs come as (lower, higher)
  EXPECT_GT(want, 0u);
  EXPECT_EQ(nl.front(), want);
  Particles walls_only = random_scene(13, 0, 50);
  nl.build(walls_only);
  EXPECT_EQ(nl.front(), 0u);
}

TEST(NeighbourList, StaysCompleteThroughARandomWalk) {
  Particles p = random_scene(11, 800, 200);
  const double skin = 0.001;
  NeighbourList nl(skin, 0.0);
  nl.build(p);
  Random rng(3);
  for (int round = 0; round < 20; ++round) {
    for (std::size_t i = 0; i < p.n_mobile; ++i)
      p.x[i] += Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)) * 0.2 * skin / std::sqrt(3.0);
    nl.update(p);
    const auto got = listed(nl, p);
    for (const auto& pr : all_pairs_within(p, 0.0)) EXPECT_TRUE(got.count(pr)) << "missed a touching pair";
  }
  EXPECT_GT(nl.builds(), 1u);  // the two largest displacements reach the skin within 20 rounds
}

// The rebuild test is d_1 + d_2 >= skin over the two largest displacements. Oracle: two balls
// placed 1 % of the skin beyond the listed distance, moved straight at each other, can touch only
// once their displacements add up to 1.01 skin, whichever of them moves.
TEST(NeighbourList, RebuildsWhenTheTwoLargestDisplacementsAddUpToTheSkin) {
  const double skin = 0.001, r = 0.004;
  Particles p;
  // A pair 1 % of the skin beyond the list's reach, and a far ball that stays put.
  p.add({Vec3(0.0, 0.0, 0.0), Vec3::Zero(), r, 1.0, 1.0, 0.0, 0, "a"}, false);
  p.add({Vec3(2 * r + 1.01 * skin, 0.0, 0.0), Vec3::Zero(), r, 1.0, 1.0, 0.0, 0, "b"}, false);
  p.add({Vec3(0.5, 0.5, 0.5), Vec3::Zero(), r, 1.0, 1.0, 0.0, 0, "far"}, false);
  NeighbourList nl(skin, 0.0);
  nl.build(p);
  ASSERT_EQ(nl.pair_count(), 0u);
  // One ball alone moves 0.9 skin toward the other: still 0.11 skin apart, and no rebuild (LAMMPS's
  // d_1 > skin/2 would rebuild here).
  p.x[0].x() += 0.9 * skin;
  EXPECT_FALSE(nl.update(p));
  EXPECT_TRUE(all_pairs_within(p, 0.0).empty());
  // The other moves 0.2 skin toward it: they now overlap by 0.09 skin, and the sum 1.1 skin forces
  // the rebuild that finds them.
  p.x[1].x() -= 0.2 * skin;
  ASSERT_EQ(all_pairs_within(p, 0.0).size(), 1u);
  EXPECT_TRUE(nl.update(p));
  EXPECT_EQ(nl.pair_count(), 1u);
  // The same at two threads: the two largest are reduced across them.
  Particles q = random_scene(21, 900, 100);
  NeighbourList one(skin, 0.0), two(skin, 0.0);
  one.build(q);
  two.build(q);
  q.x[17].y() += 0.6 * skin;
  q.x[800].z() -= 0.39 * skin;
  EXPECT_FALSE(one.update(q));
  set_threads(2);
  EXPECT_FALSE(two.update(q));
  q.x[800].z() -= 0.02 * skin;
  EXPECT_TRUE(two.update(q));
  set_threads(1);
  EXPECT_TRUE(one.update(q));
}

// The list is checked at every force evaluation, so however far a ball moves in one step (a
// fast ball moves many skins), the forces see every pair it touches where it lands: the limit on
// travel per step is the run guard's business (contacts are sampled only at the steps), not the list's.
TEST(NeighbourList, AJumpOfManySkinsInOneStepIsStillListedWhereItLands) {
  const double skin = 0.0005, r = 0.005;
  Particles p;
  p.add({Vec3(0.0, 0.0, 0.0), Vec3::Zero(), r, 1.0, 1.0, 0.0, 0, "fast"}, false);
  p.add({Vec3(0.1, 0.0, 0.0), Vec3::Zero(), r, 1.0, 1.0, 0.0, 0, "target"}, true);
  NeighbourList nl(skin, 0.0);
  nl.build(p);
  ASSERT_EQ(nl.pair_count(), 0u);
  p.x[0].x() = 0.1 - 1.5 * r;  // 183 skins in one step, into an overlap of r/2
  EXPECT_TRUE(nl.update(p));
  ASSERT_EQ(nl.pair_count(), 1u);
  EXPECT_EQ(nl.neighbour(nl.begin(0)), 1u);
}

TEST(NeighbourList, RebuildsWhenTheBallSetChanges) {
  Particles p = random_scene(5, 10, 10);
  NeighbourList nl(0.001, 0.0);
  EXPECT_TRUE(nl.update(p));
  EXPECT_FALSE(nl.update(p));
  p.add({Vec3(0.05, 0.05, 0.05), Vec3::Zero(), 0.004, 1.0, 1.0, 0.0, 0, "new"}, false);
  EXPECT_TRUE(nl.update(p));
  const auto got = listed(nl, p);
  for (const auto& pr : all_pairs_within(p, 0.0)) EXPECT_TRUE(got.count(pr));
}

TEST(NeighbourList, FarFlungBallDoesNotBlowUpTheGrid) {
  Particles p = random_scene(9, 200, 0);
  p.x[0] = Vec3(1e4, -1e4, 1e4);  // one ball 10 km away
  NeighbourList nl(0.001, 0.0);
  nl.build(p);
  const auto got = listed(nl, p);
  for (const auto& pr : all_pairs_within(p, 0.0)) EXPECT_TRUE(got.count(pr));
}

TEST(NeighbourList, WallBallsFarFromTheGrainsAreLeftOutButNoneNearIsMissed) {
  // Grains in the middle eighth of the box, walls everywhere: most walls lie beyond the grains'
  // box widened by the largest reach and are not binned; those within it must all be found.
  Random rng(11);
  Particles p;
  for (int i = 0; i < 300; ++i)
    p.add({Vec3(rng.uniform(0.04, 0.06), rng.uniform(0.04, 0.06), rng.uniform(0.04, 0.06)), Vec3::Zero(),
           rng.uniform(0.002, 0.006), 1.0, 1.0, 0.0, 0, ""}, false);
  for (int i = 0; i < 2000; ++i)
    p.add({Vec3(rng.uniform(0, 0.1), rng.uniform(0, 0.1), rng.uniform(0, 0.1)), Vec3::Zero(), rng.uniform(0.002, 0.006),
           1.0, 1.0, 0.0, 0, ""}, true);
  const double skin = 0.001, reach = 0.0005;
  NeighbourList nl(skin, reach);
  nl.build(p);
  const auto want = all_pairs_within(p, reach + skin);
  std::size_t with_wall = 0;
  for (const auto& pr : want) with_wall += p.fixed(pr.second) ? 1 : 0;
  EXPECT_GT(with_wall, 50u);  // the grains do touch walls: the test sees the wall pairs
  const std::set<std::pair<std::size_t, std::size_t>> want_set(want.begin(), want.end());
  EXPECT_EQ(listed(nl, p), want_set);
}
