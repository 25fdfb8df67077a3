#include "silodem/contact/stiffest_pair.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace silodem {

std::vector<KindPair> kind_pairs(const CaseConfig& cfg) {
  struct Kind {
    double r_min = 1e300;
    long count = 0;
  };
  std::map<std::pair<std::string, bool>, Kind> kinds;
  for (const auto& b : cfg.balls) {
    Kind& k = kinds[{b.material, b.fixed}];
    k.r_min = std::min(k.r_min, b.radius);
    ++k.count;
  }
  if (cfg.drops && cfg.drops->count > 0) {
    Kind& k = kinds[{cfg.drops->material, false}];
    k.r_min = std::min(k.r_min, cfg.drops->r_min);
    k.count += cfg.drops->count;
  }
  // Breakage: a breakable grain's fragments, down to the smallest a grain that may still break makes.
  if (cfg.breakage)
    for (auto& [key, kind] : std::map(kinds))
      if (!key.second && std::count(cfg.breakage->materials.begin(), cfg.breakage->materials.end(), key.first)) {
        Kind& k = kinds[key];
        k.r_min = std::min(k.r_min, cfg.breakage->smallest_ratio * kind.r_min / std::cbrt(double(cfg.breakage->count_max)));
        k.count += 2;
      }
  std::vector<KindPair> out;
  for (auto a = kinds.begin(); a != kinds.end(); ++a) {
    for (auto b = a; b != kinds.end(); ++b) {
      const bool fa = a->first.second, fb = b->first.second;
      if (fa && fb) continue;
      if (a == b && a->second.count < 2) continue;
      const Material& ma = cfg.materials.at(a->first.first);
      const Material& mb = cfg.materials.at(b->first.first);
      const double ra = a->second.r_min, rb = b->second.r_min;
      const double mass_a = ma.density * 4.0 / 3.0 * kPi * std::pow(ra, 3);
      const double mass_b = mb.density * 4.0 / 3.0 * kPi * std::pow(rb, 3);
      out.push_back({a->first.first + (fa ? " (fixed)" : "") + " / " + b->first.first + (fb ? " (fixed)" : ""),
                     a->first.first, b->first.first, contact::effective_mass(mass_a, mass_b, fa, fb),
                     ra * rb / (ra + rb), !fa && !fb});
    }
  }
  // A smooth wall is a fixed partner of infinite radius: R* is the ball's radius, m* its mass.
  std::set<std::string> surface_materials;
  for (const auto& s : cfg.surfaces) surface_materials.insert(s.material);
  for (const auto& sm : surface_materials)
    for (const auto& [key, kind] : kinds) {
      if (key.second) continue;
      const Material& ma = cfg.materials.at(key.first);
      out.push_back({key.first + " / " + sm + " (surface)", key.first, sm,
                     ma.density * 4.0 / 3.0 * kPi * std::pow(kind.r_min, 3), kind.r_min, false});
    }
  return out;
}

std::vector<StiffestPair> contact_pairs(const CaseConfig& cfg) {
  std::vector<StiffestPair> out;
  for (auto& kp : kind_pairs(cfg)) {
    const Material& ma = cfg.materials.at(kp.material_a);
    const Material& mb = cfg.materials.at(kp.material_b);
    const double k = contact::series(ma.k, mb.k), c = contact::series(ma.c, mb.c);
    if (k <= 0.0) continue;
    const auto beh = contact::contact_behaviour(k, c, kp.m_eff, cfg.contact.clamp);
    out.push_back({std::move(kp.description), kp.material_a, kp.material_b, k, c, kp.m_eff, beh});
  }
  return out;
}

std::optional<StiffestPair> stiffest_pair(const CaseConfig& cfg) {
  std::optional<StiffestPair> best;
  for (auto& p : contact_pairs(cfg))
    if (!best || p.behaviour.omega0 > best->behaviour.omega0) best = std::move(p);
  return best;
}

}  // namespace silodem
