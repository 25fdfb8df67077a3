#include "silodem/fill/free_fall.hpp"

#include <cmath>

namespace silodem {

std::optional<double> first_contact_height(const Vec3& start, double r0, const Vec3& xj, double rj) {
  const double dx = start.x() - xj.x(), dy = start.y() - xj.y(), dz = start.z() - xj.z();
  const double reach = r0 + rj;
  const double c = dx * dx + dy * dy + dz * dz - reach * reach;  // constant term of (15)
  const double D = dz * dz - c;                                    // = reach² − horizontal²
  if (!(D > 0.0)) return std::nullopt;
  return dz - std::sqrt(D);
}

FirstContact find_first_contact(const Particles& p, const Vec3& start, double r0) {
  FirstContact best;
  for (std::size_t j = 0; j < p.size(); ++j) {
    const auto h = first_contact_height(start, r0, p.x[j], p.r[j]);
    if (!h) continue;
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
    if (best.kind == FirstContact::Kind::NoObstacle || *h < best.h) {
      best.kind = FirstContact::Kind::Contact;
      best.h = *h;
      best.obstacle = j;
    }
  }
  return best;
}

}  // namespace silodem
