#include "silodem/fill/free_fall.hpp"

#include <cmath>
#include <vector>

namespace silodem {

std::optional<double> first_contact_height(const Vec3& start, double r0, const Vec3& xj, double rj) {
  const double dx = start.x() - xj.x(), dy = start.y() - xj.y(), dz = start.z() - xj.z();
  const double reach = r0 + rj;
  const double c = dx * dx + dy * dy + dz * dz - reach * reach;  // constant term of (15)
  const double D = dz * dz - c;                                    // = reach² − horizontal²
  if (!(D > 0.0)) return std::nullopt;
  return dz - std::sqrt(D);
}

FirstContact find_first_contact(const Particles& p, const Vec3& start, double r0, double g_abs) {
  FirstContact best;
  std::vector<std::size_t> receding_balls;
  for (std::size_t j = 0; j < p.size(); ++j) {
    const auto h = first_contact_height(start, r0, p.x[j], p.r[j]);
    if (!h) continue;
    // Receding: j falls at least as fast as the new ball will at j's height (equality holds all
    // along a free flight, so a relative margin of 1e-9 keeps drops placed in flight receding).
    const double drop = start.z() - p.x[j].z();
    const bool receding = g_abs > 0.0 && !p.fixed(j) && *h >= 0.0 && p.v[j].z() < 0.0 &&
                          p.v[j].z() * p.v[j].z() >= (1.0 - 1e-9) * 2.0 * g_abs * drop;
    if (*h < 0.0) {
      // The two roots are dz ∓ √D, so the larger one is 2 dz − h. If it is positive the start
      // sphere intersects ball j; if not, j lies entirely above the start and is no obstacle.
      const double upper = 2.0 * (start.z() - p.x[j].z()) - *h;
      if (upper > 0.0) {
        best.kind = FirstContact::Kind::StartOverlaps;
        best.obstacle = j;
        return best;
      }
      continue;
    }
    if (receding) {
      receding_balls.push_back(j);
      continue;
    }
    if (best.kind == FirstContact::Kind::NoObstacle || *h < best.h) {
      best.kind = FirstContact::Kind::Contact;
      best.h = *h;
      best.obstacle = j;
    }
  }
  // A receding ball is passed in flight, but the new ball must not be put down inside it.
  if (best.kind == FirstContact::Kind::Contact) {
    const Vec3 at = start - Vec3(0.0, 0.0, best.h);
    for (const std::size_t j : receding_balls)
      if ((at - p.x[j]).norm() < r0 + p.r[j]) {
        best.kind = FirstContact::Kind::PlacementOverlaps;
        best.obstacle = j;
        break;
      }
  }
  return best;
}

}  // namespace silodem
