#pragma once
// The stiffest pair a case can form — the one that sets the time step. Reported at start-up and
// in the summary (k, c, t_c, e and Δt/t_c), and used to resolve "dt_per_contact_time".
#include <optional>
#include <string>
#include <vector>

#include "silodem/case/case_config.hpp"
#include "silodem/contact/pair_constants.hpp"

namespace silodem {

struct StiffestPair {
  std::string description;  // e.g. "grain / wall (fixed)": the two materials, fixed balls marked
  std::string material_a, material_b;
  double k = 0.0, c = 0.0, m_eff = 0.0;
  contact::ContactBehaviour behaviour{};
};

/// A pair of ball kinds (material, fixed, smallest radius) the case can form, wall–wall excluded,
/// whatever its contact law.
struct KindPair {
  std::string description;  // as StiffestPair's
  std::string material_a, material_b;
  double m_eff = 0.0;       // the mobile ball's mass against a fixed ball
  double r_star = 0.0;      // r_a r_b / (r_a + r_b) of the smallest radii
  bool both_mobile = false;
};
std::vector<KindPair> kind_pairs(const CaseConfig& cfg);

/// Every pair of ball kinds (material, fixed, smallest radius) the case can form, wall–wall
/// excluded, with a non-zero stiffness: the candidates for the time-step limits.
std::vector<StiffestPair> contact_pairs(const CaseConfig& cfg);

/// Searches every pair of ball kinds (material, fixed, smallest radius) the case can form,
/// wall–wall excluded, for the largest ω0 = √(k_ij/m_eff).
/// Empty if no pair with a non-zero stiffness can form (a lone ball).
std::optional<StiffestPair> stiffest_pair(const CaseConfig& cfg);

}  // namespace silodem
