#pragma once
// The O(n²) search, kept only as a test oracle for the neighbour list.
#include <utility>
#include <vector>

#include "silodem/scene/particles.hpp"

namespace silodem {

/// Every pair (i < j, not both fixed) whose gap is below `reach`, i.e. |x_i − x_j| < r_i + r_j + reach.
inline std::vector<std::pair<std::size_t, std::size_t>> all_pairs_within(const Particles& p, double reach) {
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      if (p.fixed(i) && p.fixed(j)) continue;
      const double cut = p.r[i] + p.r[j] + reach;
      if ((p.x[i] - p.x[j]).squaredNorm() < cut * cut) out.emplace_back(i, j);
    }
  return out;
}

}  // namespace silodem
