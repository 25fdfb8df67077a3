#pragma once
// A smooth wall: the surface of revolution of one straight segment of a meridian profile about an
// axis (docs/model.md §11). One shape covers a cylinder (ρ constant), a cone, an annulus or a disk
// (z constant) — the walls of a silo with a hopper, as LAMMPS `region cylinder`/`cone` walls,
// LIGGGHTS meshes and YADE facets give them, without the roughness of a wall of balls; about a
// horizontal axis, a drum. A surface of revolution may spin about its own axis without changing
// its shape: only its velocity at the contact point, Ω a × (x − c), and its spin Ω a reach the
// contact laws (a mill's smooth drum, docs/model.md §12).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "silodem/case/case_config.hpp"
#include "silodem/core/types.hpp"

namespace silodem {

struct Surface {
  std::string name;
  std::int32_t material = 0;            // index into the scene's material names
  Vec3 centre = Vec3::Zero();           // a point of the axis: ρ and z are measured from it
  Vec3 axis = Vec3::UnitZ();            // unit axis direction (z grows along it)
  Vec3 across = Vec3::UnitX();          // a unit vector ⟂ axis: the normal's direction on the axis
  double rho0 = 0.0, z0 = 0.0, rho1 = 0.0, z1 = 0.0;  // the segment's ends (ρ, z)
  double angular_speed = 0.0;           // spin about the axis, rad/s, right-handed
};

inline Vec3 perpendicular_to(const Vec3& a);

/// The scene's surface of a case's surface segment; `material`: its index in the scene.
inline Surface surface_from(const SurfaceSpec& spec, std::int32_t material) {
  return {spec.name, material, spec.axis_point, spec.axis_direction, perpendicular_to(spec.axis_direction),
          spec.rho0, spec.z0, spec.rho1, spec.z1, spec.angular_speed};
}

/// A unit vector perpendicular to a unit axis (the x axis for a vertical one).
inline Vec3 perpendicular_to(const Vec3& a) {
  const Vec3 e = std::abs(a.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  return (e - e.dot(a) * a).normalized();
}

/// Where a ball centre stands against a surface: the distance to the nearest surface point and
/// the unit normal from that point to the centre.
struct SurfaceGap {
  double distance = 0.0;
  Vec3 n = Vec3::UnitZ();
};

/// The nearest point of a surface of revolution to x lies in x's meridian half-plane, so the 3-D
/// question is the 2-D distance from (ρ, z) to the segment — clamped at its ends, which makes an
/// open end (the rim of an outlet) a rounded edge. A centre on the axis takes the `across` direction.
inline SurfaceGap surface_gap(const Surface& s, const Vec3& x) {
  const Vec3 d = x - s.centre;
  const double z = d.dot(s.axis);
  const Vec3 radial = d - z * s.axis;
  const double rho = radial.norm();
  const Vec3 e = rho > 0.0 ? Vec3(radial / rho) : s.across;
  const double sr = s.rho1 - s.rho0, sz = s.z1 - s.z0;
  const double t = std::clamp(((rho - s.rho0) * sr + (z - s.z0) * sz) / (sr * sr + sz * sz), 0.0, 1.0);
  const double gr = rho - (s.rho0 + t * sr), gz = z - (s.z0 + t * sz);
  SurfaceGap g;
  g.distance = std::sqrt(gr * gr + gz * gz);
  if (g.distance > 0.0) {
    g.n = (gr * e + gz * s.axis) / g.distance;
  } else {  // the centre on the surface: the segment's own normal (a blown-up run; the guards stop it)
    const double len = std::sqrt(sr * sr + sz * sz);
    g.n = (-sz / len) * e + (sr / len) * s.axis;
  }
  return g;
}

/// The surface's velocity at a point x of it: Ω a × (x − c).
inline Vec3 surface_velocity(const Surface& s, const Vec3& x) {
  return s.angular_speed * s.axis.cross(x - s.centre);
}

}  // namespace silodem
