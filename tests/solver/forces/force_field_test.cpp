// The force loop: the pair force acts along the unit normal (6) on both balls (3), wall balls
// receive the load, and the template variants (clamp, cohesion) switch exactly their terms on.
#include <gtest/gtest.h>

#include <cmath>

#include "silodem/core/parallel.hpp"
#include "silodem/core/random.hpp"
#include "silodem/forces/force_field.hpp"

using namespace silodem;

namespace {
struct Pair {
  Particles p;
  NeighbourList nl{0.001, 1e-6};
};
Pair make(const Vec3& xj, const Vec3& vi, bool j_fixed) {
  Pair s;
  s.p.add({Vec3::Zero(), vi, 0.005, 1e-3, 2e5, 6.0, 0, "i"}, false);
  s.p.add({xj, Vec3::Zero(), 0.005, 1e-3, 2e5, 6.0, 0, "j"}, j_fixed);
  s.nl.build(s.p);
  return s;
}
}  // namespace

TEST(ForceField, ActsAlongTheNormalOnBothBalls) {
  // Centres 9 mm apart along (1, 2, 2)/3: δ = 1 mm; ball i moves towards j at 0.3 m/s along the line.
  const Vec3 n = Vec3(1, 2, 2) / 3.0;  // from i to j; n_ij (from j to i) is −n
  Pair s = make(0.009 * n, 0.3 * n, false);
  const auto field = make_force_field(ContactSpec{}, 9.81);
  const ForceTotals t = field->compute(s.p, s.nl);
  const double f = 1e5 * 0.001 + 3.0 * 0.3;  // k_ij δ + c_ij dδ/dt, series constants (11)
  EXPECT_TRUE(s.p.f[0].isApprox(-f * n, 1e-12));
  EXPECT_TRUE(s.p.f[1].isApprox(f * n, 1e-12));
  EXPECT_NEAR(t.elastic_contact, 0.5 * 1e5 * 1e-6, 1e-15);
  EXPECT_NEAR(t.p_dissipated, 3.0 * 0.09, 1e-12);
  EXPECT_NEAR(t.max_overlap_ratio, 0.2, 1e-12);
  EXPECT_EQ(t.contacts, 1u);
}

TEST(ForceField, WallBallCarriesTheLoad) {
  Pair s = make(Vec3(0, 0, -0.0099), Vec3::Zero(), true);  // resting on a wall ball below
  const auto field = make_force_field(ContactSpec{}, 9.81);
  field->compute(s.p, s.nl);
  EXPECT_NEAR(s.p.f[1].z(), -1e5 * 1e-4, 1e-9);  // pushed down: the force on the wall
  EXPECT_NEAR(s.p.f[0].z(), 1e5 * 1e-4, 1e-9);
}

TEST(ForceField, ClampAndCohesionVariants) {
  // Separating fast with a small overlap: tensile unclamped, zero clamped.
  Pair s = make(Vec3(0.00999, 0, 0), Vec3(-1.0, 0, 0), false);
  ContactSpec clamp;
  clamp.clamp = true;
  make_force_field(ContactSpec{}, 9.81)->compute(s.p, s.nl);
  EXPECT_GT(s.p.f[0].x(), 0.0);  // pulled towards j (+x): tensile
  make_force_field(clamp, 9.81)->compute(s.p, s.nl);
  EXPECT_EQ(s.p.f[0].x(), 0.0);
  // A gap inside the cohesion reach, separating: pulled back with k δ only if cohesion is on.
  ContactSpec coh;
  coh.cohesion = true;
  const double k = 1e5, dc = -0.1 * 9.81 * 1e-3 / k;  // (10)
  Pair g = make(Vec3(0.01 - 0.5 * dc, 0, 0), Vec3(-1e-3, 0, 0), false);
  make_force_field(ContactSpec{}, 9.81)->compute(g.p, g.nl);
  EXPECT_EQ(g.p.f[0].x(), 0.0);
  const ForceTotals t = make_force_field(coh, 9.81)->compute(g.p, g.nl);
  EXPECT_NEAR(g.p.f[0].x(), -k * 0.5 * dc, 1e-12);  // towards j
  EXPECT_NEAR(t.elastic_cohesion, 0.5 * k * 0.25 * dc * dc, 1e-20);
}

TEST(ForceField, PairConstantsFollowTheSeriesRuleByMaterialOrPerBall) {
  // Two materials, or one material whose balls carry different constants: both must give
  // k_ij = k_i k_j/(k_i + k_j), c_ij likewise (11).
  const auto force_on_i = [](std::int32_t mat_j, double k_j, double c_j) {
    Particles p;
    NeighbourList nl{0.001, 1e-6};
    p.add({Vec3::Zero(), Vec3(0.2, 0, 0), 0.005, 1e-3, 2e5, 6.0, 0, "i"}, false);
    p.add({Vec3(0.0095, 0, 0), Vec3::Zero(), 0.005, 1e-3, k_j, c_j, mat_j, "j"}, false);
    nl.build(p);
    make_force_field(ContactSpec{}, 9.81)->compute(p, nl);
    return -p.f[0].x();  // repulsive: pushes i towards −x
  };
  const double k = 2e5 * 5e4 / 2.5e5, c = 6.0 * 2.0 / 8.0;  // series of (2e5, 5e4) and (6, 2)
  const double expected = k * 0.0005 + c * 0.2;
  EXPECT_NEAR(force_on_i(1, 5e4, 2.0), expected, 1e-9);  // two materials: the table
  EXPECT_NEAR(force_on_i(0, 5e4, 2.0), expected, 1e-9);  // one material, per-ball constants differ
  EXPECT_NEAR(force_on_i(0, 2e5, 6.0), 1e5 * 0.0005 + 3.0 * 0.2, 1e-9);
}

TEST(ForceField, DenseBedEqualsTheAllPairsSumOnOneTwoAndThreeThreads) {
  // 3,000 polydisperse grains and 500 wall balls packed so that about half the listed pairs touch
  // (the loop selects the touching ones before the law): every ball's force and the energy sums
  // must equal an O(n²) sum of the closed-form law (4)(5)(6)(11) over all pairs, over several
  // chunks of the force loop and on both of its paths (scatter, store-and-gather).
  Random rng(17);
  Particles p;
  for (int i = 0; i < 3500; ++i) {
    const Vec3 x(rng.uniform(0, 0.14), rng.uniform(0, 0.14), rng.uniform(0, 0.14));
    p.add({x, Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)), rng.uniform(0.004, 0.006),
           rng.uniform(1e-3, 2e-3), rng.uniform(1e5, 3e5), rng.uniform(1.0, 5.0), 0, ""},
          i >= 3000);
  }
  NeighbourList nl(0.003, 0.0);  // a wide skin: with random centres about half the listed pairs touch
  nl.build(p);
  std::vector<Vec3> want(p.size(), Vec3::Zero());
  double elastic = 0.0, dissipated = 0.0;
  std::size_t touching = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      if (p.fixed(i) && p.fixed(j)) continue;
      const Vec3 d = p.x[i] - p.x[j];
      const double delta = p.r[i] + p.r[j] - d.norm();
      if (delta <= 0.0) continue;
      const Vec3 n = d.normalized();
      const double k = p.k[i] * p.k[j] / (p.k[i] + p.k[j]), c = p.c[i] * p.c[j] / (p.c[i] + p.c[j]);
      const double rate = -(p.v[i] - p.v[j]).dot(n), f = k * delta + c * rate;
      want[i] += f * n;
      want[j] -= f * n;
      elastic += 0.5 * k * delta * delta;
      dissipated += c * rate * rate;
      ++touching;
    }
  ASSERT_GT(touching, nl.pair_count() / 3);  // a dense bed: many listed pairs touch, many do not
  ASSERT_LT(touching, nl.pair_count() * 2 / 3);
  // Balls in random order: nearly every pair crosses the threads' ranges. Each field computes
  // twice: the second call runs on ranges moved by the first call's timings.
  std::vector<Vec3> one_thread;
  for (const int threads : {1, 2, 3}) {
    const auto field = make_force_field(ContactSpec{}, 9.81);
    for (int call = 0; call < 2; ++call) {
      set_threads(threads);
      for (auto& f : p.f) f = Vec3::Constant(1e9);  // stale forces must not leak through
      const ForceTotals t = field->compute(p, nl);
      set_threads(1);
      EXPECT_EQ(t.contacts, touching);
      EXPECT_NEAR(t.elastic_contact, elastic, 1e-12 * elastic);
      EXPECT_NEAR(t.p_dissipated, dissipated, 1e-12 * dissipated);
      for (std::size_t i = 0; i < p.size(); ++i)
        ASSERT_LT((p.f[i] - want[i]).norm(), 1e-9 * (1.0 + want[i].norm())) << "ball " << i << ", threads " << threads;
      if (threads == 1) one_thread = p.f;
      for (std::size_t i = 0; i < p.size(); ++i)  // the same bits on any thread count
        ASSERT_EQ(p.f[i], one_thread[i]) << "ball " << i << ", threads " << threads << ", call " << call;
    }
  }
}
