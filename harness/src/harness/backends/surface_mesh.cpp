#include "harness/backends/surface_mesh.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace harness {

namespace {

using Point = std::array<double, 3>;

std::string facet(const Point& a, const Point& b, const Point& c) {
  const Point u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  Point n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (double& x : n) x /= len;
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "facet normal %.17g %.17g %.17g\nouter loop\nvertex %.17g %.17g %.17g\nvertex %.17g %.17g %.17g\n"
                "vertex %.17g %.17g %.17g\nendloop\nendfacet\n",
                n[0], n[1], n[2], a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2]);
  return buf;
}

}  // namespace

std::string surface_stl(const silodem::SurfaceSpec& s, int segments, double max_aspect) {
  const double half = std::numbers::pi / segments;
  const double scale = half / std::sin(half);
  // Rows along the profile, so that no triangle is longer than max_aspect times its narrowest width.
  const double slant = std::hypot(s.rho1 - s.rho0, s.z1 - s.z0);
  const double rho_min = std::min(s.rho0, s.rho1) > 0.0 ? std::min(s.rho0, s.rho1) : 0.5 * std::max(s.rho0, s.rho1);
  const double narrowest = 2.0 * half * rho_min;
  const int rows = std::max(1, int(std::ceil(slant / (max_aspect * narrowest))));
  auto point = [&](int row, int k) {
    const double f = double(row) / rows, rho = s.rho0 + f * (s.rho1 - s.rho0), z = s.z0 + f * (s.z1 - s.z0);
    const double phi = 2.0 * half * k;
    return Point{s.axis_point.x() + scale * rho * std::cos(phi), s.axis_point.y() + scale * rho * std::sin(phi), z};
  };
  std::string stl = "solid " + s.name + "\n";
  for (int row = 0; row < rows; ++row)
    for (int k = 0; k < segments; ++k) {
      const Point a0 = point(row, k), a1 = point(row, k + 1), b0 = point(row + 1, k), b1 = point(row + 1, k + 1);
      stl += facet(a0, a1, b1);
      stl += facet(a0, b1, b0);
    }
  return stl + "endsolid " + s.name + "\n";
}

}  // namespace harness
