#pragma once
// Which balls a process holds in a run shared among MPI processes (docs/domain-decomposition.md):
//   - it owns a contiguous range of the global ball order (the renumbering of
//     neighbour/spatial_order.hpp), cut at edges of the sum chunks, equal counts per process;
//   - it holds as ghosts the other processes' balls that lie within reach of its own (a pair's
//     largest list distance plus a margin), refreshed from their owners before every force evaluation;
//   - it holds every wall ball.
// Locally the balls are in global order: lower ghosts, owned balls, upper ghosts, walls. Each
// process then computes exactly the sums one process computes for the same balls (core/partition.hpp).
//
// Redistribution, between steps, when the global order is renumbered: every process gathers all
// owned balls and their contact history (version 1 of the decomposition: O(N) on every process
// for that moment; a parallel sample sort is what would remove it), cuts the ranges again and
// chooses its ghosts. When balls have moved half the margin since the ghosts were chosen, only
// the ghosts are chosen again, from what each owner sends.
#include <cstdint>
#include <vector>

#include "silodem/forces/force_field.hpp"
#include "silodem/integrate/integrator.hpp"
#include "silodem/mpi/mpi_partition.hpp"
#include "silodem/scene/particles.hpp"

namespace silodem::mpi {

class Domain {
 public:
  /// `pair_reach`: the farthest two balls' centres can be and still be listed (2 r_max + the
  /// cohesion reach + the skin). `margin`: how far beyond it ghosts are kept, so that they
  /// stay enough while the balls move less than half of it.
  Domain(MpiPartition& part, double pair_reach, double margin) : part_(part), pair_reach_(pair_reach), margin_(margin) {}

  /// Keeps this process's share of the whole scene `p` (which every process built alike).
  void distribute(Particles& p, Integrator& integrator);
  /// Gathers every process's balls, renumbers them if `renumber`, and shares them out again
  /// with their integrator state and contact history.
  void redistribute(Particles& p, Integrator& integrator, ForceField& field, bool renumber);
  /// Chooses the ghosts again around the same own balls (balls moved, the order is unchanged):
  /// each owner sends what lies in another's box. The contact history stays: a ghost that was not
  /// one before was too far to touch an own ball, and the pairs kept keep their state by tags.
  void reselect_ghosts(Particles& p, Integrator& integrator);
  /// The ghosts' positions, velocities and spins, from their owners.
  void refresh_ghosts(Particles& p) const;
  /// After a step: whether the balls have moved far enough for a redistribution to be due. Throws
  /// a RunError if they moved so far in one step that a ghost may have been missing.
  bool redistribution_due(const Particles& p) const;

  std::size_t global_mobile() const { return global_mobile_; }
  std::size_t redistributions() const { return redistributions_; }
  std::size_t ghosts() const { return ghost_global_.size(); }

  /// One mobile ball as it moves between processes.
  struct Record {
    Particles::Ball ball;
    Vec3 a = Vec3::Zero(), alpha = Vec3::Zero();
  };
  /// Every process's owned balls, in global order, on every process.
  std::vector<Record> gather_owned(const Particles& p, const Integrator* integrator) const;

 private:
  void share(std::vector<Record> all, Particles& p, Integrator& integrator, bool carried);

  MpiPartition& part_;
  double pair_reach_, margin_;
  std::size_t global_mobile_ = 0, redistributions_ = 0;
  std::vector<std::size_t> range_begin_;    // per rank, and the total last: the cut of the global order
  std::vector<std::uint64_t> ghost_global_;  // global index of each ghost, in local order
  std::vector<std::vector<std::uint32_t>> send_;  // per rank: the owned local indices it takes as ghosts
  std::vector<std::vector<std::uint32_t>> recv_;  // per rank: the local ghost indices it refreshes
  std::vector<Vec3> x_at_share_;             // owned balls' positions when the ghosts were chosen
};

}  // namespace silodem::mpi
