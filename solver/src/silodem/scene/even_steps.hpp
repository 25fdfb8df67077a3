#pragma once
// Evenly spaced wall-ball positions along a line, shared by the wall builders.
#include <algorithm>
#include <cmath>
#include <vector>

namespace silodem {

/// n + 1 evenly spaced values from a to b, at most `step` apart (the one value a when b <= a).
inline std::vector<double> even_steps(double a, double b, double step) {
  const int n = b > a ? std::max(1, int(std::ceil((b - a) / step - 1e-9))) : 0;
  std::vector<double> out;
  for (int k = 0; k <= n; ++k) out.push_back(n ? a + (b - a) * k / n : a);
  return out;
}

}  // namespace silodem
