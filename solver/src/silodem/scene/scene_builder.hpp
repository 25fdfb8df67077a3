#pragma once
// Case → particles: the balls the case lists (mobile and wall), with masses from their material
// density (docs/model.md §1: m = ρ 4/3 π r³) and per-ball k_i, c_i from the derived material.
#include <string>
#include <vector>

#include "silodem/case/case_config.hpp"
#include "silodem/scene/particles.hpp"

namespace silodem {

struct Scene {
  Particles particles;
  std::vector<std::string> material_names;  // index = Particles::material
  std::int32_t material_index(const std::string& name) const;
};

Scene build_scene(const CaseConfig& cfg);

/// Dump tag of drop number k (0-based attempt index): after the listed balls.
inline std::int64_t drop_tag(const CaseConfig& cfg, long k) { return std::int64_t(cfg.balls.size()) + 1 + k; }

inline double sphere_mass(double density, double r) { return density * 4.0 / 3.0 * kPi * r * r * r; }

}  // namespace silodem
