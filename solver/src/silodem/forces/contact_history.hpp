#pragma once
// Per-contact state of the history laws (the tangential spring ξ, the rolling spring θ_r; docs/model.md
// §10.2, §10.5): `Springs` vectors per contact, each of which changes sign with the pair's order. One entry per
// slot of the neighbour list, so each contact's state lives with the ball that owns its slot, as
// LAMMPS's `fix neigh/history` keeps it per atom. Two buffers: `committed` is the state at the
// end of the last accepted step, `trial` what the latest force evaluation made of it. Every
// evaluation reads committed and writes trial, so the corrector passes of a step, and a thread
// that recomputes a neighbour's pair, all see the same input; commit() accepts the step.
// When the list is rebuilt (balls moved, renumbered, added, removed, fixed), the committed state
// moves to the new slots by the two balls' tags, never by index: a contact that is listed again
// keeps its state, a contact that ended had none left (the force loop clears it at separation).
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

#include "silodem/core/types.hpp"
#include "silodem/neighbour/neighbour_list.hpp"
#include "silodem/scene/particles.hpp"

namespace silodem {

class Archive;

template <int Springs>
class ContactHistory {
 public:
  using State = Eigen::Matrix<double, 3, Springs>;  // one column per spring

  /// Brings the committed state onto the list's current slots (a no-op unless it was rebuilt).
  void follow(const NeighbourList& list, const Particles& p);
  const State& committed(std::size_t slot) const { return committed_[slot]; }
  State& trial(std::size_t slot) { return trial_[slot]; }
  /// The slots [begin, end) are about to be evaluated: a contact not written again has ended.
  void clear_trial(std::size_t begin, std::size_t end) { std::fill(trial_.begin() + long(begin), trial_.begin() + long(end), State::Zero()); }
  /// The step is accepted: its last evaluation's state becomes the committed one.
  void commit() { committed_.swap(trial_); }
  /// f(owner tag, neighbour tag, committed state) for each slot whose column `col` is set in the
  /// committed state and clear in the trial one: a contact the step being accepted ended.
  template <class F>
  void for_each_ended(int col, F&& f) const {
    for (std::size_t s = 0; s < committed_.size(); ++s)
      if (committed_[s](2, col) != 0.0 && trial_[s](2, col) == 0.0) f(owner_tag_[s], neighbour_tag_[s], committed_[s]);
  }
  /// The committed states of the slots stored under balls [begin, end) at the followed build, as
  /// records: owner tag, neighbour tag (int64 each), the state (3 × Springs doubles).
  std::vector<char> export_owned(std::size_t begin, std::size_t end) const;
  /// Replaces the committed state by such records; the next follow() places them by tags.
  void adopt(const std::vector<char>& records);
  /// Bytes of one record.
  static constexpr std::size_t kRecordBytes = 2 * sizeof(std::int64_t) + sizeof(State);
  /// Contacts with a non-zero committed state.
  std::size_t active() const;
  /// Checkpoint: the committed state and the tags it belongs to, in slot order.
  void serialize(Archive& a, const NeighbourList& list);
  std::size_t bytes() const {
    return heap_bytes(committed_) + heap_bytes(trial_) + heap_bytes(owner_tag_) + heap_bytes(neighbour_tag_) + heap_bytes(offsets_);
  }
  /// Bytes per listed pair (two buffers and the two tags).
  static constexpr std::size_t kBytesPerSlot = 2 * sizeof(State) + 2 * sizeof(std::int64_t);

 private:
  std::vector<State> committed_, trial_;
  void follow_same_balls(const NeighbourList& list, const Particles& p);
  void follow_by_tags(const NeighbourList& list, const Particles& p);
  std::vector<std::int64_t> owner_tag_, neighbour_tag_;  // per slot, at the build the state follows
  std::vector<std::size_t> offsets_;                     // that build's first slot of each mobile ball
  std::uint64_t topology_ = ~std::uint64_t(0);           // Particles::topology at that build
  std::size_t builds_ = ~std::size_t(0);                 // that build's count (NeighbourList::builds)
  bool adopted_ = false;                                 // holds adopt()ed records no follow() has placed yet
};

}  // namespace silodem
