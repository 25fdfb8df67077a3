#include "silodem/forces/contact_history.hpp"

#include <algorithm>
#include <stdexcept>
#include <tuple>

#include "silodem/checkpoint/archive.hpp"

namespace silodem {

namespace {
/// A contact's state keyed by its unordered pair of tags, stored as seen from the lower tag: ξ is
/// the displacement of one ball relative to the other, so it changes sign with the order.
template <class State>
struct Keyed {
  std::int64_t low, high;
  State state;
  bool operator<(const Keyed& o) const { return std::tie(low, high) < std::tie(o.low, o.high); }
};
}  // namespace

template <int Springs>
void ContactHistory<Springs>::follow(const NeighbourList& list, const Particles& p) {
  if (list.builds() == builds_ && committed_.size() == list.pair_count()) return;
  if (p.topology == topology_ && offsets_.size() == p.n_mobile + 1)
    follow_same_balls(list, p);
  else
    follow_by_tags(list, p);
  const std::size_t n = list.pair_count();
  trial_.assign(n, State::Zero());
  adopted_ = false;
  owner_tag_.resize(n);
  neighbour_tag_.resize(n);
  for (std::size_t s = 0; s < n; ++s) owner_tag_[s] = p.tag[list.owner(s)], neighbour_tag_[s] = p.tag[list.neighbour(s)];
  offsets_.resize(p.n_mobile + 1);
  for (std::size_t i = 0; i <= p.n_mobile; ++i) offsets_[i] = i < p.n_mobile ? list.begin(i) : n;
  topology_ = p.topology;
  builds_ = list.builds();
}

/// The balls kept their indices since the last build (no renumbering, no ball added or removed):
/// a pair keeps its owner, so its state is among the owner's few former slots.
template <int Springs>
void ContactHistory<Springs>::follow_same_balls(const NeighbourList& list, const Particles& p) {
  std::vector<State> moved(list.pair_count(), State::Zero());
  for (std::size_t i = 0; i < p.n_mobile; ++i)
    for (std::size_t s = list.begin(i); s < list.end(i); ++s) {
      const std::int64_t b = p.tag[list.neighbour(s)];
      for (std::size_t o = offsets_[i]; o < offsets_[i + 1]; ++o)
        if (neighbour_tag_[o] == b) {
          moved[s] = committed_[o];
          break;
        }
    }
  committed_.swap(moved);
}

/// Any change of indices: the state of every contact that has one, keyed by its pair of tags.
template <int Springs>
void ContactHistory<Springs>::follow_by_tags(const NeighbourList& list, const Particles& p) {
  std::vector<Keyed<State>> kept;
  for (std::size_t s = 0; s < committed_.size(); ++s) {
    if (committed_[s].isZero(0.0)) continue;
    const std::int64_t a = owner_tag_[s], b = neighbour_tag_[s];
    kept.push_back(a < b ? Keyed<State>{a, b, committed_[s]} : Keyed<State>{b, a, State(-committed_[s])});
  }
  std::sort(kept.begin(), kept.end());
  const std::size_t n = list.pair_count();
  committed_.assign(n, State::Zero());
  if (kept.empty()) return;
  for (std::size_t s = 0; s < n; ++s) {
    const std::int64_t a = p.tag[list.owner(s)], b = p.tag[list.neighbour(s)];
    const Keyed<State> key{std::min(a, b), std::max(a, b), State::Zero()};
    const auto it = std::lower_bound(kept.begin(), kept.end(), key);
    if (it != kept.end() && it->low == key.low && it->high == key.high) committed_[s] = a < b ? it->state : State(-it->state);
  }
}

template <int Springs>
std::vector<char> ContactHistory<Springs>::export_owned(std::size_t begin, std::size_t end) const {
  std::vector<char> out;
  // Adopted records wait for the next follow() to find their slots; exported before that, they
  // would be lost. A redistribution always has a force evaluation between it and the next.
  if (adopted_) throw std::logic_error("ContactHistory::export_owned: adopted records not yet placed");
  if (offsets_.empty() || committed_.empty()) return out;  // no force evaluation yet: no contact
  for (std::size_t s = offsets_.at(begin); s < offsets_.at(end); ++s) {
    if (committed_[s].isZero(0.0)) continue;
    const std::size_t at = out.size();
    out.resize(at + kRecordBytes);
    std::memcpy(&out[at], &owner_tag_[s], sizeof(std::int64_t));
    std::memcpy(&out[at + sizeof(std::int64_t)], &neighbour_tag_[s], sizeof(std::int64_t));
    std::memcpy(&out[at + 2 * sizeof(std::int64_t)], committed_[s].data(), sizeof(State));
  }
  return out;
}

template <int Springs>
void ContactHistory<Springs>::adopt(const std::vector<char>& records) {
  const std::size_t n = records.size() / kRecordBytes;
  committed_.assign(n, State::Zero());
  owner_tag_.resize(n);
  neighbour_tag_.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const char* at = &records[k * kRecordBytes];
    std::memcpy(&owner_tag_[k], at, sizeof(std::int64_t));
    std::memcpy(&neighbour_tag_[k], at + sizeof(std::int64_t), sizeof(std::int64_t));
    std::memcpy(committed_[k].data(), at + 2 * sizeof(std::int64_t), sizeof(State));
  }
  trial_.assign(n, State::Zero());
  offsets_.clear();
  adopted_ = true;
  topology_ = ~std::uint64_t(0);  // not this list's slots: placed by tags at the next follow()
  builds_ = ~std::size_t(0);
}

template <int Springs>
std::size_t ContactHistory<Springs>::active() const {
  return std::size_t(std::count_if(committed_.begin(), committed_.end(), [](const State& s) { return !s.isZero(0.0); }));
}

template <int Springs>
void ContactHistory<Springs>::serialize(Archive& a, const NeighbourList& list) {
  a & committed_ & owner_tag_ & neighbour_tag_ & builds_;
  if (a.loading()) {
    if (committed_.size() != list.pair_count() || owner_tag_.size() != committed_.size() ||
        neighbour_tag_.size() != committed_.size() || builds_ != list.builds())
      throw CheckpointError("checkpoint payload is damaged (contact history for another neighbour list)");
    for (const State& s : committed_)
      if (!s.allFinite()) throw CheckpointError("checkpoint payload is damaged (a contact history is not finite)");
    trial_.assign(committed_.size(), State::Zero());
  }
}

template class ContactHistory<1>;
template class ContactHistory<2>;
template class ContactHistory<3>;

}  // namespace silodem
