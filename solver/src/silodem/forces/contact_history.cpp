#include "silodem/forces/contact_history.hpp"

#include <algorithm>
#include <tuple>

#include "silodem/checkpoint/archive.hpp"

namespace silodem {

namespace {
/// A contact's state keyed by its unordered pair of tags, stored as seen from the lower tag: ξ is
/// the displacement of one ball relative to the other, so it changes sign with the order.
struct Keyed {
  std::int64_t low, high;
  Vec3 state;
  bool operator<(const Keyed& o) const { return std::tie(low, high) < std::tie(o.low, o.high); }
};
}  // namespace

void ContactHistory::follow(const NeighbourList& list, const Particles& p) {
  if (list.builds() == builds_ && committed_.size() == list.pair_count()) return;
  std::vector<Keyed> kept;
  for (std::size_t s = 0; s < committed_.size(); ++s) {
    if (committed_[s].isZero(0.0)) continue;
    const std::int64_t a = owner_tag_[s], b = neighbour_tag_[s];
    kept.push_back(a < b ? Keyed{a, b, committed_[s]} : Keyed{b, a, Vec3(-committed_[s])});
  }
  std::sort(kept.begin(), kept.end());
  const std::size_t n = list.pair_count();
  committed_.assign(n, Vec3::Zero());
  trial_.assign(n, Vec3::Zero());
  owner_tag_.resize(n);
  neighbour_tag_.resize(n);
  for (std::size_t s = 0; s < n; ++s) {
    const std::int64_t a = p.tag[list.owner(s)], b = p.tag[list.neighbour(s)];
    owner_tag_[s] = a;
    neighbour_tag_[s] = b;
    if (kept.empty()) continue;
    const Keyed key{std::min(a, b), std::max(a, b), Vec3::Zero()};
    const auto it = std::lower_bound(kept.begin(), kept.end(), key);
    if (it != kept.end() && it->low == key.low && it->high == key.high) committed_[s] = a < b ? it->state : Vec3(-it->state);
  }
  builds_ = list.builds();
}

std::size_t ContactHistory::active() const {
  return std::size_t(std::count_if(committed_.begin(), committed_.end(), [](const Vec3& s) { return !s.isZero(0.0); }));
}

void ContactHistory::serialize(Archive& a, const NeighbourList& list) {
  a & committed_ & owner_tag_ & neighbour_tag_ & builds_;
  if (a.loading()) {
    if (committed_.size() != list.pair_count() || owner_tag_.size() != committed_.size() ||
        neighbour_tag_.size() != committed_.size() || builds_ != list.builds())
      throw CheckpointError("checkpoint payload is damaged (contact history for another neighbour list)");
    for (const Vec3& s : committed_)
      if (!s.allFinite()) throw CheckpointError("checkpoint payload is damaged (a contact history is not finite)");
    trial_.assign(committed_.size(), Vec3::Zero());
  }
}

}  // namespace silodem
