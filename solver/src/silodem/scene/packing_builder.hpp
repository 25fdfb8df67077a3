#pragma once
// Mobile grains generated from a description in the case (`generate`, docs/case-format.md):
// a simple cubic lattice or a random loose packing (random sequential addition) inside a box, a
// vertical cylinder or a silo (a cylinder over a conical hopper), radii uniform on [r_min, r_max],
// drawn from the generator's seed. The case file stays a few hundred bytes for any number of
// grains, and every code gets the same balls: they are made once, when the case is loaded.
#include <cstdint>
#include <string>
#include <vector>

#include "silodem/case/case_config.hpp"

namespace silodem {

struct PackingRegion {
  enum class Shape { Box, Cylinder, Silo } shape = Shape::Box;
  Vec3 min = Vec3::Zero(), max = Vec3::Zero();  // box
  double cx = 0.0, cy = 0.0, radius = 0.0;      // cylinder and silo: vertical axis through (cx, cy)
  double z_lo = 0.0, z_hi = 0.0;                // cylinder and silo (z_lo: the silo's outlet)
  double outlet_radius = 0.0, half_angle = 0.0;  // silo: the hopper's outlet radius and half-angle (rad)
};

struct PackingSpec {
  std::string name;      // ball ids are <name>_<k>, k from 0
  std::string kind;      // "lattice" or "random"
  std::string material;
  double r_min = 0.0, r_max = 0.0;
  PackingRegion region;
  long count = -1;       // lattice: at most this many (-1: every site); random: exactly this many
  double spacing = 0.0;  // lattice: centre distance, ≥ 2 r_max
  double clearance = 0.0;  // gap kept between a grain and the region's boundary, m
  Vec3 velocity = Vec3::Zero();
  std::uint64_t seed = 0;
};

/// The region's bounding box (for sampling and for the lattice's sites).
void region_bounds(const PackingRegion& g, Vec3& lo, Vec3& hi);
/// Whether a ball of radius `reach` (radius plus clearance) about `c` lies wholly inside the region.
bool inside_region(const PackingRegion& g, const Vec3& c, double reach);

/// Lattice sites inside the region bottom-up (z, then y, then x), at most `count` (-1: all), or
/// all of the random packing's `count` grains. Throws std::runtime_error saying how many fit when
/// the region is too small (the case loader turns it into a CaseError at the generator's path).
std::vector<BallSpec> build_packing(const PackingSpec& spec);

}  // namespace silodem
