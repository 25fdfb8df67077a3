// The sweep order (neighbour/spatial_order.hpp): a permutation of the mobile balls, slab by slab
// along the longest extent, and Particles::permute_mobile moves every ball's whole state with it.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "silodem/neighbour/spatial_order.hpp"

namespace {

silodem::Particles random_box(std::size_t n, const silodem::Vec3& size, unsigned seed) {
  silodem::Particles p;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    silodem::Particles::Ball b;
    b.x = silodem::Vec3(u(rng) * size.x(), u(rng) * size.y(), u(rng) * size.z());
    b.v = silodem::Vec3(u(rng), u(rng), u(rng));
    b.r = 0.001 + 0.001 * u(rng);
    b.m = b.r * 1e3, b.k = 1e4, b.c = 1.0, b.material = 0;
    b.id = "b" + std::to_string(i), b.tag = std::int64_t(i + 1);
    p.add(b, false);
  }
  silodem::Particles::Ball wall{silodem::Vec3(0, 0, -1), silodem::Vec3::Zero(), 0.01, 1.0, 1e4, 1.0, 0, "w", 0};
  p.add(wall, true);
  return p;
}

}  // namespace

TEST(SweepOrder, IsAPermutationInSlabsAlongTheLongestAxis) {
  // Longest along y, then z, then x: the key is (y cell, z cell, x cell).
  const double cell = 0.004;
  const auto p = random_box(3000, silodem::Vec3(0.05, 0.4, 0.1), 3);
  const auto order = silodem::sweep_order(p, cell);
  ASSERT_EQ(order.size(), p.n_mobile);
  std::vector<std::uint32_t> sorted(order);
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t k = 0; k < sorted.size(); ++k) ASSERT_EQ(sorted[k], k);
  silodem::Vec3 lo = p.x[0];
  for (std::size_t i = 0; i < p.n_mobile; ++i) lo = lo.cwiseMin(p.x[i]);
  const auto key = [&](std::uint32_t i) {
    const silodem::Vec3 c = (p.x[i] - lo) / cell;
    return std::make_tuple(long(c.y()), long(c.z()), long(c.x()), i);
  };
  for (std::size_t k = 1; k < order.size(); ++k) EXPECT_LT(key(order[k - 1]), key(order[k])) << k;
}

TEST(SweepOrder, PermuteMobileCarriesEveryBallsStateAndLeavesWallsAlone) {
  auto p = random_box(500, silodem::Vec3(0.1, 0.1, 0.3), 5);
  const auto before = p;
  const auto order = silodem::sweep_order(p, 0.003);
  p.permute_mobile(order);
  EXPECT_NE(p.topology, before.topology);  // index caches must refresh
  for (std::size_t k = 0; k < p.n_mobile; ++k) {
    const std::size_t i = order[k];
    EXPECT_EQ(p.id[k], before.id[i]);
    EXPECT_EQ(p.tag[k], before.tag[i]);
    EXPECT_EQ(p.x[k], before.x[i]);
    EXPECT_EQ(p.v[k], before.v[i]);
    EXPECT_EQ(p.r[k], before.r[i]);
    EXPECT_EQ(p.m[k], before.m[i]);
  }
  EXPECT_EQ(p.id.back(), "w");
  EXPECT_EQ(p.find("b17"), std::ptrdiff_t(std::find(order.begin(), order.end(), 17u) - order.begin()));
  EXPECT_THROW(p.permute_mobile({0, 1}), std::invalid_argument);
}
