#pragma once
// A smooth wall: the surface of revolution of one straight segment of a meridian profile about a
// vertical axis (docs/model.md §11). One shape covers a cylinder (ρ constant), a cone, an annulus
// or a disk (z constant) — the walls of a silo with a hopper, as LAMMPS `region cylinder`/`cone`
// walls, LIGGGHTS meshes and YADE facets give them, without the roughness of a wall of balls.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "silodem/core/types.hpp"

namespace silodem {

struct Surface {
  std::string name;
  std::int32_t material = 0;       // index into the scene's material names
  double axis_x = 0.0, axis_y = 0.0;
  double rho0 = 0.0, z0 = 0.0, rho1 = 0.0, z1 = 0.0;  // the segment's ends (ρ, z)
};

/// Where a ball centre stands against a surface: the distance to the nearest surface point and
/// the unit normal from that point to the centre.
struct SurfaceGap {
  double distance = 0.0;
  Vec3 n = Vec3::UnitZ();
};

/// The nearest point of a surface of revolution to x lies in x's meridian half-plane, so the 3-D
/// question is the 2-D distance from (ρ, z) to the segment — clamped at its ends, which makes an
/// open end (the rim of an outlet) a rounded edge. A centre on the axis takes the x direction.
inline SurfaceGap surface_gap(const Surface& s, const Vec3& x) {
  const double dx = x.x() - s.axis_x, dy = x.y() - s.axis_y;
  const double rho = std::sqrt(dx * dx + dy * dy);
  const double ex = rho > 0.0 ? dx / rho : 1.0, ey = rho > 0.0 ? dy / rho : 0.0;
  const double sr = s.rho1 - s.rho0, sz = s.z1 - s.z0;
  const double t = std::clamp(((rho - s.rho0) * sr + (x.z() - s.z0) * sz) / (sr * sr + sz * sz), 0.0, 1.0);
  const double gr = rho - (s.rho0 + t * sr), gz = x.z() - (s.z0 + t * sz);
  SurfaceGap g;
  g.distance = std::sqrt(gr * gr + gz * gz);
  if (g.distance > 0.0) {
    g.n = Vec3(gr * ex, gr * ey, gz) / g.distance;
  } else {  // the centre on the surface: the segment's own normal (a blown-up run; the guards stop it)
    const double len = std::sqrt(sr * sr + sz * sz);
    g.n = Vec3(-sz / len * ex, -sz / len * ey, sr / len);
  }
  return g;
}

}  // namespace silodem
