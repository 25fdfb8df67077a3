#pragma once
// Run guards (issue 6): cheap tests after every step that stop a run which has gone wrong —
// non-finite state, an overlap deeper than a set fraction of the smaller radius, energy being
// created (the ledger's balance against the energy moved), a ball leaving the domain — or that
// ran into its step or wall-clock limit. Each throws RunError naming the ball (or pair), where,
// the step and time, and the likely cause (the time step against that pair's contact time).
#include <chrono>

#include "silodem/case/case_config.hpp"
#include "silodem/energy/energy_ledger.hpp"
#include "silodem/forces/force_field.hpp"
#include "silodem/neighbour/neighbour_list.hpp"
#include "silodem/scene/particles.hpp"

namespace silodem {

class Archive;

class RunGuards {
 public:
  /// The domain is the bounding box of the balls at start and of the drop release points,
  /// widened by spec.domain_margin; outflow (run/stages) removes balls before they reach it.
  RunGuards(const CaseConfig& cfg, const Particles& p);
  /// Throws RunError if a guard trips after `step` (t = step · dt).
  void check(const Particles& p, const NeighbourList& list, const ForceTotals& totals, const EnergyState& ledger,
             long step, double t) const;

  /// Checkpoint: the domain (made from the balls at the start) and the wall clock used so far.
  void serialize(Archive& a);

 private:
  const CaseConfig& cfg_;
  Vec3 lo_, hi_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace silodem
