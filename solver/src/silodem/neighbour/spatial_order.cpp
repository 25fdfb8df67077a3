#include "silodem/neighbour/spatial_order.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace silodem {

std::array<int, 3> sweep_axes(const Vec3& span) {
  std::array<int, 3> axis{0, 1, 2};
  std::stable_sort(axis.begin(), axis.end(), [&](int a, int b) { return span[a] > span[b]; });
  return axis;
}

std::vector<std::uint32_t> sweep_order(const Particles& p, double cell) {
  const std::size_t n = p.n_mobile;
  std::vector<std::uint32_t> order(n);
  if (n == 0) return order;
  Vec3 lo = p.x[0], hi = p.x[0];
  for (std::size_t i = 0; i < n; ++i) {
    lo = lo.cwiseMin(p.x[i]);
    hi = hi.cwiseMax(p.x[i]);
  }
  // Axes by extent, longest first: the sweep runs along the longest axis, so its front (one
  // slab across the two shorter ones) is the smallest.
  const Vec3 span = hi - lo;
  const std::array<int, 3> axis = sweep_axes(span);
  // At most 2^21 cells per axis; a wider scene gets coarser cells (a looser order, never a wrong
  // one). A non-finite position is the run guards' business: it sorts as cell 0 here.
  const double edge = std::max(cell, span.maxCoeff() / double((1u << 21) - 1));
  const auto q = [&](const Vec3& x, int d) -> std::uint64_t {
    const double c = edge > 0.0 ? (x[d] - lo[d]) / edge : 0.0;
    return c >= 0.0 && c < double(1u << 21) ? std::uint64_t(c) : 0u;
  };
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(n);
  for (std::size_t i = 0; i < n; ++i)
    keyed[i] = {q(p.x[i], axis[0]) << 42 | q(p.x[i], axis[1]) << 21 | q(p.x[i], axis[2]), std::uint32_t(i)};
  std::sort(keyed.begin(), keyed.end());  // by key, then by index
  for (std::size_t k = 0; k < n; ++k) order[k] = keyed[k].second;
  return order;
}

}  // namespace silodem
