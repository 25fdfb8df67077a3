#pragma once
// Basic types shared by every stage of the solver.
#include <Eigen/Core>
#include <cstddef>
#include <numbers>

namespace silodem {

using Vec3 = Eigen::Vector3d;
inline constexpr double kPi = std::numbers::pi;

}  // namespace silodem
