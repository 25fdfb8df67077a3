#pragma once
// The force loop: every listed pair through the contact law, forces on both balls (3), and the
// energy terms the ledger needs. The law's options (cohesion, clamp) are template parameters,
// chosen once per scene by make_force_field(): an unused feature costs nothing in the loop.
#include <cstdint>
#include <memory>
#include <vector>

#include "silodem/case/case_config.hpp"
#include "silodem/neighbour/neighbour_list.hpp"
#include "silodem/scene/particles.hpp"

namespace silodem {

class Archive;

/// Sums over all pairs at the evaluated state.
struct ForceTotals {
  double elastic_contact = 0.0;   // Σ ½ k δ² over overlapping pairs, J
  double elastic_cohesion = 0.0;  // Σ ½ k δ² over active cohesion springs, J
  double p_dissipated = 0.0;      // dashpot power, W (≥ 0)
  double p_cohesion = 0.0;        // power into cohesion springs, W (≥ 0)
  double max_overlap_ratio = 0.0; // max δ / min(r_i, r_j)
  std::size_t contacts = 0;       // pairs with δ > 0
  // Friction and rolling resistance (forces/frictional_field.cpp); zero in a frictionless scene.
  double elastic_tangential = 0.0;  // Σ ½ k_t |ξ|² over tangential springs, J
  double elastic_rolling = 0.0;     // Σ ½ k_r |θ_r|² over rolling springs (EPSD), J
  double p_friction = 0.0;          // power the tangential and rolling laws take from the balls, W
  std::size_t sliding = 0;          // contacts at the Coulomb cap

  /// Adds one contact's energy terms (a contact::Interaction of the frictional law).
  template <class Interaction>
  void add(const Interaction& r) {
    elastic_contact += r.elastic_normal;
    p_dissipated += r.p_dissipated;
    elastic_tangential += r.elastic_tangential;
    elastic_rolling += r.elastic_rolling;
    p_friction += r.p_friction;
    sliding += std::size_t(r.sliding);
    ++contacts;
  }
};

/// A contact that ended in an accepted step (breakage/breakage_stage.hpp): its balls' tags and the
/// largest elastic energy its normal law held, J.
struct ContactEnd {
  std::int64_t tag_i = 0, tag_j = 0;
  double energy = 0.0;
};

class ForceField {
 public:
  virtual ~ForceField() = default;
  /// Zeroes p.f and accumulates the contact forces of every listed pair at the current (x, v).
  virtual ForceTotals compute(Particles& p, const NeighbourList& list) const = 0;
  /// Heap bytes of its scratch buffers.
  virtual std::size_t bytes() const = 0;
  /// The step is accepted: per-contact history becomes what its last evaluation made of it
  /// (forces/contact_history.hpp). Nothing to do for a law without history.
  virtual void commit() {}
  /// Breakage: the contacts that ended since the last call (none without breakage).
  virtual std::vector<ContactEnd> take_ended_contacts() { return {}; }
  /// Breakage: these balls were just born overlapping others; contacts they have at their first
  /// evaluation carry no force until they end (notes B11).
  virtual void set_newborn(std::vector<std::int64_t> /*tags*/) {}
  /// Checkpoint of the per-contact history (none without a history law).
  virtual void serialize_history(Archive&, const NeighbourList&) {}
  /// The committed contact history of the pairs stored under balls [begin, end) as records
  /// (owner tag, neighbour tag, state), for balls that move to another process (mpi/domain.hpp).
  virtual std::vector<char> export_history(std::size_t /*begin*/, std::size_t /*end*/) const { return {}; }
  /// A partitioned scene (core/partition.hpp): makes the wall balls' forces those of the last
  /// evaluation, summed across processes (left stale by compute). Nothing to do otherwise.
  virtual void finish_walls(Particles& /*p*/, const NeighbourList& /*list*/) const {}
  /// Replaces the contact history by such records; the next force evaluation finds them by tags.
  virtual void adopt_history(const std::vector<char>& /*records*/) {}
};

/// `g_abs` scales the cohesion reach (10); `dt` is the time step (needed by spec.onset_correction).
std::unique_ptr<ForceField> make_force_field(const ContactSpec& spec, double g_abs, double dt = 0.0);
/// A case's force loop: the one above for the paper's frictionless law, else the frictional one
/// (forces/frictional_field.hpp), whose pair constants come from the case's materials.
std::unique_ptr<ForceField> make_force_field(const CaseConfig& cfg);

/// Largest cohesion reach |δ_c| any pair of these balls can have (0 without cohesion) — how far
/// beyond touching the neighbour list must look.
/// `extra_mass_max`, `extra_k_min`: the heaviest mass and smallest stiffness of balls still to come (drops).
double max_cohesion_reach(const Particles& p, const ContactSpec& spec, double g_abs, double extra_mass_max,
                          double extra_k_min);

}  // namespace silodem
