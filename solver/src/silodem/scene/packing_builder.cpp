#include "silodem/scene/packing_builder.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "silodem/case/limits.hpp"
#include "silodem/core/random.hpp"

namespace silodem {

void region_bounds(const PackingRegion& g, Vec3& lo, Vec3& hi) {
  if (g.shape == PackingRegion::Shape::Box) {
    lo = g.min, hi = g.max;
    return;
  }
  lo = Vec3(g.cx - g.radius, g.cy - g.radius, g.z_lo);
  hi = Vec3(g.cx + g.radius, g.cy + g.radius, g.z_hi);
}

bool inside_region(const PackingRegion& g, const Vec3& c, double reach) {
  if (g.shape == PackingRegion::Shape::Box)
    return (c.array() - reach >= g.min.array()).all() && (c.array() + reach <= g.max.array()).all();
  if (c.z() - reach < g.z_lo || c.z() + reach > g.z_hi) return false;
  const double rho = std::hypot(c.x() - g.cx, c.y() - g.cy);
  double wall = g.radius - reach;
  // The cone's wall is at horizontal distance reach / cos β from a grain touching it.
  if (g.shape == PackingRegion::Shape::Silo)
    wall = std::min(wall, g.outlet_radius + (c.z() - g.z_lo) * std::tan(g.half_angle) - reach / std::cos(g.half_angle));
  return rho <= wall;
}

namespace {

BallSpec grain(const PackingSpec& s, std::size_t k, const Vec3& at, double radius) {
  BallSpec b;
  b.id = s.name + "_" + std::to_string(k);
  b.material = s.material;
  b.radius = radius;
  b.position = at;
  b.velocity = s.velocity;
  return b;
}

std::vector<BallSpec> lattice(const PackingSpec& s, Random& rng) {
  Vec3 lo, hi;
  region_bounds(s.region, lo, hi);
  const double reach = s.r_max + s.clearance;
  const Vec3 first = lo.array() + reach;
  const Vec3 span = (hi - lo).array() - 2.0 * reach;
  if ((span.array() < 0.0).any()) throw std::runtime_error("the region is narrower than one grain");
  const long nx = long(span.x() / s.spacing) + 1, ny = long(span.y() / s.spacing) + 1, nz = long(span.z() / s.spacing) + 1;
  if (double(nx) * double(ny) * double(nz) > 1e10) throw std::runtime_error("more than 1e10 lattice sites: the spacing is far too small for the region");
  std::vector<BallSpec> balls;
  for (long k = 0; k < nz; ++k)
    for (long j = 0; j < ny; ++j)
      for (long i = 0; i < nx; ++i) {
        if (s.count >= 0 && long(balls.size()) == s.count) return balls;
        if (double(balls.size()) >= limits::kGeneratedBalls)
          throw std::runtime_error("the region holds more than " + std::to_string(long(limits::kGeneratedBalls)) +
                                   " lattice sites; give a count or a larger spacing");
        const Vec3 at = first + s.spacing * Vec3(double(i), double(j), double(k));
        if (!inside_region(s.region, at, reach)) continue;
        balls.push_back(grain(s, balls.size(), at, rng.uniform(s.r_min, s.r_max)));
      }
  if (s.count >= 0 && long(balls.size()) < s.count)
    throw std::runtime_error("the region holds " + std::to_string(balls.size()) + " lattice sites at spacing " +
                             std::to_string(s.spacing) + " m, fewer than count " + std::to_string(s.count));
  return balls;
}

/// Random sequential addition: a grain at a uniform random place is kept if it overlaps no grain
/// kept before. It jams near a solid fraction of 0.38 for equal spheres (a loose packing).
std::vector<BallSpec> random_loose(const PackingSpec& s, Random& rng) {
  Vec3 lo, hi;
  region_bounds(s.region, lo, hi);
  const Vec3 size = hi - lo;
  const double volume = std::max(size.prod(), 0.0);
  // Cells at least a grain diameter wide (neighbours lie in the 27 around), and no more than grains.
  double h = std::max(2.0 * s.r_max, std::cbrt(volume / double(std::max(1L, s.count))));
  const auto cells_along = [&](double length) { return std::max(1L, long(std::min(length / h, 1e9))); };
  // A flat region has one cell across its thin side: widen the cells until there are at most two a grain.
  while (double(cells_along(size.x())) * double(cells_along(size.y())) * double(cells_along(size.z())) >
         2.0 * double(std::max(1L, s.count)) + 8.0)
    h *= 1.25;
  const long nx = cells_along(size.x()), ny = cells_along(size.y()), nz = cells_along(size.z());
  const Vec3 cell(size.x() / double(nx), size.y() / double(ny), size.z() / double(nz));
  std::vector<std::int32_t> head(std::size_t(nx * ny * nz), -1), next;
  const auto cell_of = [&](const Vec3& c, long& i, long& j, long& k) {
    i = std::clamp(long((c.x() - lo.x()) / cell.x()), 0L, nx - 1);
    j = std::clamp(long((c.y() - lo.y()) / cell.y()), 0L, ny - 1);
    k = std::clamp(long((c.z() - lo.z()) / cell.z()), 0L, nz - 1);
  };
  std::vector<BallSpec> balls;
  balls.reserve(std::size_t(s.count));
  next.reserve(std::size_t(s.count));
  const long max_attempts = 200 * s.count + 10000;
  long attempts = 0;
  while (long(balls.size()) < s.count && attempts++ < max_attempts) {
    const double r = rng.uniform(s.r_min, s.r_max);
    const Vec3 at(rng.uniform(lo.x(), hi.x()), rng.uniform(lo.y(), hi.y()), rng.uniform(lo.z(), hi.z()));
    if (!inside_region(s.region, at, r + s.clearance)) continue;
    long ci, cj, ck;
    cell_of(at, ci, cj, ck);
    bool free = true;
    for (long k = std::max(0L, ck - 1); free && k <= std::min(nz - 1, ck + 1); ++k)
      for (long j = std::max(0L, cj - 1); free && j <= std::min(ny - 1, cj + 1); ++j)
        for (long i = std::max(0L, ci - 1); free && i <= std::min(nx - 1, ci + 1); ++i)
          for (std::int32_t b = head[std::size_t((k * ny + j) * nx + i)]; free && b >= 0; b = next[std::size_t(b)])
            free = (balls[std::size_t(b)].position - at).norm() >= balls[std::size_t(b)].radius + r;
    if (!free) continue;
    const std::size_t c = std::size_t((ck * ny + cj) * nx + ci);
    next.push_back(head[c]);
    head[c] = std::int32_t(balls.size());
    balls.push_back(grain(s, balls.size(), at, r));
  }
  if (long(balls.size()) < s.count)
    throw std::runtime_error("random loose packing placed " + std::to_string(balls.size()) + " of " +
                             std::to_string(s.count) + " grains in " + std::to_string(max_attempts) +
                             " attempts: the region is too small (random addition jams near a solid fraction of "
                             "0.38); give a larger region, fewer grains or a lattice");
  return balls;
}

}  // namespace

std::vector<BallSpec> build_packing(const PackingSpec& spec) {
  Random rng(spec.seed);
  return spec.kind == "lattice" ? lattice(spec, rng) : random_loose(spec, rng);
}

}  // namespace silodem
