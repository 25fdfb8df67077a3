#pragma once
// Verlet neighbour list with a skin, built in O(n) from a cell grid. Half list in CSR form: each
// pair is stored once, under its mobile ball (mobile–mobile under the lower index, mobile–wall
// under the mobile one); wall–wall pairs are never stored — wall balls overlap each other by
// design and must not interact. Correct for polydisperse radii: the cell edge is the largest
// possible pair reach, and each pair is tested against its own r_i + r_j + reach + skin.
#include <cstdint>
#include <vector>

#include "silodem/scene/particles.hpp"

namespace silodem {

class Archive;

class NeighbourList {
 public:
  /// `skin`: extra distance a pair may close before the list must be rebuilt.
  /// `reach`: how far beyond touching a pair still interacts (the largest cohesion reach |δ_c|).
  NeighbourList(double skin, double reach) : skin_(skin), reach_(reach) {}

  /// Rebuilds when the two largest displacements of mobile balls since the last build add up
  /// to the skin, or the particle set changed. Returns true if it rebuilt.
  bool update(const Particles& p);
  void build(const Particles& p);

  std::size_t begin(std::size_t i) const { return offsets_[i]; }
  std::size_t end(std::size_t i) const { return offsets_[i + 1]; }
  std::uint32_t neighbour(std::size_t slot) const { return list_[slot]; }
  /// The ball i a slot is stored under (begin(i) <= slot < end(i)): lets the force loop walk the
  /// slots of many balls as one flat run.
  std::uint32_t owner(std::size_t slot) const { return owner_[slot]; }
  /// The slots where ball j is the neighbour, in increasing order (every ball, walls included):
  /// the force loop gathers the reactions on j from them in a fixed order, whatever the threads.
  std::size_t reverse_begin(std::size_t j) const { return reverse_offsets_[j]; }
  std::size_t reverse_end(std::size_t j) const { return reverse_offsets_[j + 1]; }
  std::uint32_t reverse_slot(std::size_t k) const { return reverse_slots_[k]; }
  std::size_t pair_count() const { return list_.size(); }
  /// The sweep's front: the largest index distance from a mobile ball to a mobile neighbour stored
  /// under it. The force loop prefetches that far ahead.
  std::size_t front() const { return front_; }
  std::size_t builds() const { return builds_; }
  double skin() const { return skin_; }
  /// How far beyond touching a pair may interact (the largest cohesion reach), as constructed.
  double reach() const { return reach_; }
  /// Checkpoint: the list in its order (the force sums follow it, so a rebuilt list would change
  /// the last bits), the positions at the build and the build count. Reading checks every index
  /// against `p`, which must be loaded first.
  void serialize(Archive& a, const Particles& p);
  std::size_t chunk_bytes() const {
    std::size_t b = 0;
    for (const auto& c : chunk_lists_) b += heap_bytes(c);
    return b;
  }
  std::size_t bytes() const {
    return heap_bytes(offsets_) + heap_bytes(list_) + heap_bytes(owner_) + heap_bytes(reverse_offsets_) + heap_bytes(reverse_slots_) +
           heap_bytes(x_at_build_) + heap_bytes(cell_start_) + heap_bytes(cell_balls_) + heap_bytes(ball_cell_) +
           heap_bytes(cell_fill_) + heap_bytes(reverse_fill_) +
           chunk_bytes();
  }

 private:
  double skin_, reach_;
  std::vector<std::size_t> offsets_;   // n_mobile + 1 entries
  std::vector<std::uint32_t> list_;
  std::vector<std::uint32_t> owner_;  // per slot, made from offsets_ (not stored in checkpoints)
  void fill_owners();
  void measure_front();  // needs the owners and the reverse index
  std::size_t front_ = 0;
  std::vector<std::size_t> reverse_offsets_;  // size() + 1 entries
  std::vector<std::uint32_t> reverse_slots_;
  std::vector<Vec3> x_at_build_;
  std::uint64_t topology_at_build_ = ~std::uint64_t(0);
  std::size_t builds_ = 0;
  // Cell grid scratch, kept between builds to avoid reallocation.
  std::vector<std::uint32_t> cell_start_, cell_balls_, ball_cell_, cell_fill_;
  std::vector<std::size_t> reverse_fill_;
  std::vector<std::vector<std::uint32_t>> chunk_lists_;  // per chunk of balls, joined into list_
};

}  // namespace silodem
