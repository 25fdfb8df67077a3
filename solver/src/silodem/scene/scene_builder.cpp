#include "silodem/scene/scene_builder.hpp"

#include <algorithm>
#include <stdexcept>

namespace silodem {

std::int32_t Scene::material_index(const std::string& name) const {
  const auto it = std::find(material_names.begin(), material_names.end(), name);
  if (it == material_names.end()) throw std::out_of_range("no material " + name);
  return std::int32_t(it - material_names.begin());
}

Scene build_scene(const CaseConfig& cfg) {
  Scene s;
  for (const auto& [name, m] : cfg.materials) s.material_names.push_back(name);
  // The listed balls and every drop the case may place (recycled drops reuse their balls).
  if (cfg.contact.rotation()) s.particles.enable_rotation();  // before the balls: they get ω = 0
  s.particles.planar = cfg.dimension == 2;
  s.particles.inertia_factor = cfg.inertia_factor;
  s.particles.reserve(cfg.balls.size() + (cfg.drops ? std::size_t(std::max(0L, cfg.drops->count)) : 0));
  std::int64_t tag = 0;
  for (const auto& b : cfg.balls) {
    const Material& m = cfg.materials.at(b.material);
    s.particles.add({b.position, b.velocity, b.radius, sphere_mass(m.density, b.radius), m.k, m.c,
                     s.material_index(b.material), b.id, ++tag, b.angular_velocity},
                    b.fixed);
  }
  return s;
}

}  // namespace silodem
