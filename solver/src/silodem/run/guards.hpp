#pragma once
// Run guards (issue 6): cheap tests after every step that stop a run which has gone wrong —
// a non-finite position, velocity, force or ledger term (nothing non-finite reaches a result
// file: the guards run before the step's output), an overlap deeper than a set fraction of the
// smaller radius, a ball moving so far per step that it could pass through a ball unseen, energy
// being created (the ledger's balance against the energy moved), a ball leaving the domain — or
// that ran into its step or wall-clock limit. Each throws RunError naming the ball (or pair), where,
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
  /// Throws for the first mobile ball the scan found wrong: non-finite, out of the domain, too fast.
  void name_offender(const Particles& p, const NeighbourList& list, long step, double t) const;

  const CaseConfig& cfg_;
  Vec3 lo_, hi_;
  double r_min_ = 0.0;       // smallest radius of the scene, m
  double max_speed2_ = 0.0;  // (guards.max_travel_ratio · r_min / Δt)², m²/s²
  std::chrono::steady_clock::time_point start_;
  // Steps in a row on which the ledger's drift was beyond its limit. A blow-up keeps it there; the
  // ratio's noise while the energy moved is tiny (a run's start, a moving wall's first touch of a
  // grain at rest) does not last. Not in the checkpoint: a restart counts afresh.
  mutable long steps_drifting_ = 0;
};

}  // namespace silodem
