#pragma once
#include <cstddef>
#include <vector>
// Basic types shared by every stage of the solver.
#include <Eigen/Core>
#include <cstddef>
#include <numbers>

namespace silodem {

/// Bytes a vector holds on the heap (its capacity), for the memory figures of summary.json.
template <class T>
std::size_t heap_bytes(const std::vector<T>& v) {
  return v.capacity() * sizeof(T);
}

using Vec3 = Eigen::Vector3d;
inline constexpr double kPi = std::numbers::pi;

}  // namespace silodem
