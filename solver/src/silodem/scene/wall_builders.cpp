#include "silodem/scene/wall_builders.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "silodem/core/random.hpp"
#include "silodem/scene/drum_builder.hpp"
#include "silodem/scene/tray_builder.hpp"

namespace silodem {

namespace {

struct Placer {
  const WallSpec& w;
  Random rng;
  std::vector<BallSpec> out;
  /// A ball whose surface touches the nominal wall at `surface`, its centre `normal_out` beyond it.
  void place(const Vec3& surface, const Vec3& normal_out) {
    BallSpec b;
    b.radius = w.r_min + (w.r_max - w.r_min) * rng.uniform();
    // Centres at the mean radius behind the surface: radius scatter shows as roughness, as in the paper.
    b.position = surface + 0.5 * (w.r_min + w.r_max) * normal_out;
    b.id = w.name + "_" + std::to_string(out.size());
    b.material = w.material;
    b.fixed = true;
    out.push_back(b);
  }
};

}  // namespace

std::vector<BallSpec> build_wall(const WallSpec& w, std::uint64_t seed) {
  Placer pl{w, Random(seed), {}};
  if (w.type == "tray") return build_tray(w, pl.rng);
  if (w.type == "drum") return build_drum(w, pl.rng);
  const double s = w.spacing;
  if (w.type == "cylinder") {
    const double R = 0.5 * w.diameter;
    const int n_theta = std::max(3, int(std::ceil(2.0 * kPi * R / s)));
    const int n_z = std::max(1, int(std::ceil(w.height / s)) + 1);
    for (int k = 0; k < n_z; ++k) {
      const double z = w.centre.z() + w.height * k / std::max(1, n_z - 1);
      // Alternate rows are shifted half a step: a staggered (triangular) net closes the holes.
      const double shift = (k % 2) * 0.5;
      for (int i = 0; i < n_theta; ++i) {
        const double th = 2.0 * kPi * (i + shift) / n_theta;
        const Vec3 out(std::cos(th), std::sin(th), 0.0);
        pl.place(Vec3(w.centre.x(), w.centre.y(), z) + R * out, out);
      }
    }
  } else if (w.type == "disk") {
    // Concentric rings from the hole (or the centre) to the rim, surface at centre.z, facing up.
    const double r0 = 0.5 * w.hole_diameter, r1 = 0.5 * w.diameter;
    if (r0 == 0.0) pl.place(w.centre, Vec3(0, 0, -1));
    const int rings = std::max(1, int(std::ceil((r1 - r0) / s)));
    for (int k = (r0 == 0.0 ? 1 : 0); k <= rings; ++k) {
      const double rho = r0 + (r1 - r0) * k / rings;
      const int n = std::max(3, int(std::ceil(2.0 * kPi * rho / s)));
      for (int i = 0; i < n; ++i) {
        const double th = 2.0 * kPi * (i + 0.5 * (k % 2)) / n;
        pl.place(w.centre + Vec3(rho * std::cos(th), rho * std::sin(th), 0.0), Vec3(0, 0, -1));
      }
    }
  } else if (w.type == "cone") {
    // Hopper: top ring of diameter `diameter` at centre.z, down to `hole_diameter` at centre.z − height.
    const double r_top = 0.5 * w.diameter, r_bot = 0.5 * w.hole_diameter;
    const double slant = std::hypot(r_top - r_bot, w.height);
    const Vec3 dn((w.height) / slant, 0.0, -(r_top - r_bot) / slant);  // outward normal in the (r, z) plane
    const int rows = std::max(1, int(std::ceil(slant / s)));
    for (int k = 0; k <= rows; ++k) {
      const double f = double(k) / rows;
      const double rho = r_bot + (r_top - r_bot) * f, z = w.centre.z() - w.height * (1.0 - f);
      const int n = std::max(3, int(std::ceil(2.0 * kPi * rho / s)));
      for (int i = 0; i < n; ++i) {
        const double th = 2.0 * kPi * (i + 0.5 * (k % 2)) / n;
        const Vec3 radial(std::cos(th), std::sin(th), 0.0);
        const Vec3 normal = dn.x() * radial + Vec3(0, 0, dn.z());
        pl.place(Vec3(w.centre.x(), w.centre.y(), z) + rho * radial, normal);
      }
    }
  }
  return pl.out;
}

double largest_hole(const WallSpec& w, const std::vector<BallSpec>& balls) {
  const double s = w.spacing, step = s / 12.0;
  // Wall balls hashed on a grid of cells 2s wide: a sample only looks at its own 27 cells.
  const double cell = 2.0 * s + 2.0 * w.r_max;
  const auto key = [&](long i, long j, long k) { return (i * 73856093) ^ (j * 19349663) ^ (k * 83492791); };
  std::unordered_multimap<long, std::size_t> grid;
  for (std::size_t n = 0; n < balls.size(); ++n) {
    const Vec3& x = balls[n].position;
    grid.emplace(key(long(std::floor(x.x() / cell)), long(std::floor(x.y() / cell)), long(std::floor(x.z() / cell))), n);
  }
  double worst = 0.0;
  const auto probe = [&](const Vec3& x) {
    double gap = INFINITY;
    const long ci = long(std::floor(x.x() / cell)), cj = long(std::floor(x.y() / cell)), ck = long(std::floor(x.z() / cell));
    for (long i = ci - 1; i <= ci + 1; ++i)
      for (long j = cj - 1; j <= cj + 1; ++j)
        for (long k = ck - 1; k <= ck + 1; ++k) {
          const auto range = grid.equal_range(key(i, j, k));
          for (auto it = range.first; it != range.second; ++it) {
            const BallSpec& b = balls[it->second];
            gap = std::min(gap, (b.position - x).norm() - b.radius);
          }
        }
    worst = std::max(worst, gap);
  };
  if (w.type == "tray" || w.type == "drum") {
    for (const Vec3& x : w.type == "tray" ? tray_surface_samples(w, step) : drum_surface_samples(w, step)) probe(x);
  } else if (w.type == "cylinder") {
    const double R = 0.5 * w.diameter;
    for (double z = w.centre.z(); z <= w.centre.z() + w.height; z += step)
      for (double th = 0.0; th < 2.0 * kPi; th += step / R)
        probe(Vec3(w.centre.x() + R * std::cos(th), w.centre.y() + R * std::sin(th), z));
  } else if (w.type == "disk") {
    for (double x = -0.5 * w.diameter; x <= 0.5 * w.diameter; x += step)
      for (double y = -0.5 * w.diameter; y <= 0.5 * w.diameter; y += step) {
        const double rho = std::hypot(x, y);
        if (rho > 0.5 * w.diameter || rho < 0.5 * w.hole_diameter + s) continue;
        probe(w.centre + Vec3(x, y, 0.0));
      }
  } else if (w.type == "cone") {
    const double r_top = 0.5 * w.diameter, r_bot = 0.5 * w.hole_diameter;
    for (double f = 0.0; f <= 1.0; f += step / std::hypot(r_top - r_bot, w.height)) {
      const double rho = r_bot + (r_top - r_bot) * f, z = w.centre.z() - w.height * (1.0 - f);
      if (rho < r_bot + s) continue;  // the outlet rim
      for (double th = 0.0; th < 2.0 * kPi; th += step / rho)
        probe(Vec3(w.centre.x() + rho * std::cos(th), w.centre.y() + rho * std::sin(th), z));
    }
  }
  return worst;
}

}  // namespace silodem
