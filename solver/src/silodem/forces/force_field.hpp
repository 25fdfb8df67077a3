#pragma once
// The force loop: every listed pair through the contact law, forces on both balls (3), and the
// energy terms the ledger needs. The law's options (cohesion, clamp) are template parameters,
// chosen once per scene by make_force_field(): an unused feature costs nothing in the loop.
#include <memory>

#include "silodem/case/case_config.hpp"
#include "silodem/neighbour/neighbour_list.hpp"
#include "silodem/scene/particles.hpp"

namespace silodem {

/// Sums over all pairs at the evaluated state.
struct ForceTotals {
  double elastic_contact = 0.0;   // Σ ½ k δ² over overlapping pairs, J
  double elastic_cohesion = 0.0;  // Σ ½ k δ² over active cohesion springs, J
  double p_dissipated = 0.0;      // dashpot power, W (≥ 0)
  double p_cohesion = 0.0;        // power into cohesion springs, W (≥ 0)
  double max_overlap_ratio = 0.0; // max δ / min(r_i, r_j)
  std::size_t contacts = 0;       // pairs with δ > 0
};

class ForceField {
 public:
  virtual ~ForceField() = default;
  /// Zeroes p.f and accumulates the contact forces of every listed pair at the current (x, v).
  virtual ForceTotals compute(Particles& p, const NeighbourList& list) const = 0;
  /// Heap bytes of its scratch buffers.
  virtual std::size_t bytes() const = 0;
};

/// `g_abs` scales the cohesion reach (10); `dt` is the time step (needed by spec.onset_correction).
std::unique_ptr<ForceField> make_force_field(const ContactSpec& spec, double g_abs, double dt = 0.0);

/// Largest cohesion reach |δ_c| any pair of these balls can have (0 without cohesion) — how far
/// beyond touching the neighbour list must look.
/// `extra_mass_max`, `extra_k_min`: the heaviest mass and smallest stiffness of balls still to come (drops).
double max_cohesion_reach(const Particles& p, const ContactSpec& spec, double g_abs, double extra_mass_max,
                          double extra_k_min);

}  // namespace silodem
