#include "silodem/run/wall_motion.hpp"

namespace silodem {

double move_walls(Particles& p, double dt) {
  const double power = wall_power(p);
  for (std::size_t i = p.n_mobile; i < p.size(); ++i)
    if (!p.v[i].isZero()) p.x[i] += dt * p.v[i];
  return power;
}

double wall_power(const Particles& p) {
  double power = 0.0;
  for (std::size_t i = p.n_mobile; i < p.size(); ++i) power -= p.f[i].dot(p.v[i]);
  return power;
}

}  // namespace silodem
