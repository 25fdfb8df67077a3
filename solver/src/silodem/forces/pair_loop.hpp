#pragma once
// The loop mechanics of every contact law: which pairs to evaluate, in what order, on which
// thread, what to prefetch, and how forces and torques reach both balls. The physics is the Law
// (forces/kelvin_voigt_law.hpp, forces/frictional_law.hpp), a small class this loop calls per
// pair; nothing here knows what a contact does.
//
// A Law provides:
//   static constexpr bool kTorques;           // it returns torques (a rotating scene)
//   bool selected(p, i, j, reach) const;      // the pair can interact now (a test without branches)
//   template <bool Owner> PairResult<kTorques> evaluate(p, s, i, j, ForceTotals&, OverlapMax&) const;
//                                             // zero if apart; the owner's call stores the history
//   void skip(s_begin, s_end) const;          // slots about to be evaluated: clear their history
//   std::array<HintArray, 8> hint_arrays(p) const;  // the per-ball arrays it reads, for prefetch
//   void prepare(p, list), commit(), serialize_history(a, list); std::size_t bytes() const;
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <utility>
#include <vector>

#include "silodem/core/parallel.hpp"
#include "silodem/core/partition.hpp"
#include "silodem/forces/force_field.hpp"

namespace silodem {

/// What one pair does to its two balls: the force on its owner i (the reaction on j), and with a
/// rotating law the torques about both centres.
template <bool Torques>
struct PairResult {
  Vec3 f = Vec3::Zero();
};
template <>
struct PairResult<true> {
  Vec3 f = Vec3::Zero(), torque_i = Vec3::Zero(), torque_j = Vec3::Zero();
};

/// Running maximum of δ / min(r_i, r_j) kept as the fraction itself: comparing δ_a r_b > δ_b r_a
/// needs no division per contact.
struct OverlapMax {
  double delta = 0.0, r = 1.0;
  void take(double d, double r_min) {
    if (d * r > delta * r_min) delta = d, r = r_min;
  }
  double ratio() const { return delta / r; }
};

/// One per-ball array the loop asks the hardware for ahead of use.
struct HintArray {
  const char* base;
  std::size_t stride;
  template <class T>
  static HintArray of(const std::vector<T>& a) { return {reinterpret_cast<const char*>(a.data()), sizeof(T)}; }
};

namespace pair_loop {

/// Balls per chunk: the unit of the energy sums (the same chunks on any thread count, so the same
/// bits) and of the selection pass, and the step in which threads' ranges move. Small, so that
/// the ranges can balance finely: on the 5,000-ball anchor bed 256 gives 20 chunks.
constexpr std::size_t kChunk = 256;

/// How far ahead of the owner the loop prefetches: one sweep front and a margin. Capped so that
/// what is fetched early still fits the last-level cache when the order has decayed (balls mixing
/// between renumberings) and the front is long.
constexpr std::size_t kAheadMargin = 64, kMaxAhead = 16384;

/// Below this many mobile balls the loop's data (about 350 bytes a ball with its list) fits this
/// VM's last-level cache and there is nothing to hide. Measured (reports/perf_experiments.md):
/// 300,000 balls tiled, 8 % faster with the prefetch; 100,000, no slower; 20,000, within noise.
constexpr std::size_t kPrefetchFromBalls = 50000;

/// What the pairs of one chunk add to the totals: outward (neighbour beyond the chunk) and inward.
struct ChunkTotals {
  ForceTotals out, in;
  OverlapMax om_out, om_in;
};

/// Asks, one hint per call, for the lines of a ball that the loop will read before it does. A
/// ball's data is first read when it is the farthest partner of a ball one sweep front below it,
/// in no order the hardware prefetcher follows across the arrays: at 10^5-10^6 balls those loads
/// stalled the loop. The hints rotate through eight arrays, one per slot: all arrays at every
/// slot cost issue slots and hid less (reports/perf_experiments.md). Read hints only: with
/// threads, the lines past a range belong to a thread that writes their forces.
class AheadHints {
 public:
  explicit AheadHints(const std::array<HintArray, 8>& round) : round_(round) {}
  void next(std::size_t ball) {
    __builtin_prefetch(round_[at_].base + ball * round_[at_].stride);
    at_ = (at_ + 1) & 7u;
  }

 private:
  std::array<HintArray, 8> round_;
  unsigned at_ = 0;
};

}  // namespace pair_loop

/// One thread: a single pass in ball order — ball i starts from the reactions of the pairs of
/// lower balls (already scattered onto it), adds the pairs it owns and scatters their reactions.
/// More threads: each takes one run of consecutive balls (a range of whole chunks) and does the
/// same inside it. A ball first gathers the reactions of the pairs it has with balls of lower
/// ranges, computing those pairs itself (their owners compute them too, for their own force: the
/// same bits), so no thread waits for another; pairs reaching a higher range add only to their
/// owner; pairs with walls are stored, and each wall sums its stored reactions, in slot order, on
/// the thread that stored its last one: right after that thread's range if it stored them all,
/// after one barrier if a lower range stored some. Every ball's force is the same sum in the same
/// order as on one thread: the same bits for any thread count (core/parallel.hpp). Energy terms
/// are summed per chunk — outward pairs, then inward pairs, each in slot order — then over chunks
/// in order. A chunk first selects its interacting pairs, then runs the law on those alone, in
/// slot order: the same sums as a pass over every slot.
template <class Law>
class PairLoop final : public ForceField {
  static constexpr bool kTorques = Law::kTorques;
  using Result = PairResult<kTorques>;

 public:
  explicit PairLoop(Law law) : law_(std::move(law)) {}

  ForceTotals compute(Particles& p, const NeighbourList& list) const override {
    law_.prepare(p, list);
    if (const Partition* part = partition()) return compute_share(p, list, *part);
    return threads() == 1 ? compute_with<true>(p, list) : compute_with<false>(p, list);
  }
  void commit() override { law_.commit(); }
  std::vector<ContactEnd> take_ended_contacts() override {
    if constexpr (requires { law_.take_ended(); }) return law_.take_ended();
    return {};
  }
  void set_newborn(std::vector<std::int64_t> tags) override {
    if constexpr (requires { law_.set_newborn(tags); }) law_.set_newborn(std::move(tags));
  }
  void serialize_history(Archive& a, const NeighbourList& list) override { law_.serialize_history(a, list); }
  std::vector<char> export_history(std::size_t begin, std::size_t end) const override {
    if constexpr (requires { law_.export_history(begin, end); }) return law_.export_history(begin, end);
    return {};
  }
  void adopt_history(const std::vector<char>& records) override {
    if constexpr (requires { law_.adopt_history(records); }) law_.adopt_history(records);
  }

  std::size_t bytes() const override {
    std::size_t b = heap_bytes(pair_f_) + heap_bytes(pair_t_) + heap_bytes(stored_in_) + heap_bytes(partial_) + law_.bytes();
    for (const auto& w : spanning_) b += heap_bytes(w);
    for (const auto& w : selected_) b += heap_bytes(w);
    return b;
  }

 private:
  /// The slots in [s_begin, s_end) whose balls can interact now, in slot order, into `out`. No
  /// branch on the data: about half the listed pairs of a dense bed touch, in an order no branch
  /// predictor learns, and a mispredicted branch per pair stalls the long sqrt–divide chain of
  /// the law; the pairs that pass then go through the law back to back. One flat run of slots: a
  /// loop per ball and its few slots was 8 % slower on the 20,000-ball bed.
  template <bool Prefetch>
  std::size_t select_interacting(const Particles& p, const NeighbourList& list, std::size_t s_begin, std::size_t s_end,
                                 std::size_t ahead_limit, std::uint32_t* out) const {
    const std::size_t ahead = std::min(list.front(), pair_loop::kMaxAhead) + pair_loop::kAheadMargin;
    pair_loop::AheadHints hints(law_.hint_arrays(p));
    std::size_t n = 0;
    for (std::size_t s = s_begin; s < s_end; ++s) {
      out[n] = std::uint32_t(s);
      const std::uint32_t i = list.owner(s), j = list.neighbour(s);
      if constexpr (Prefetch) hints.next(std::min(i + ahead, ahead_limit));  // once per slot: no branch
      n += std::size_t(law_.selected(p, i, j, list.reach()));
    }
    return n;
  }

  /// Selects the interacting slots of the balls [i_begin, i_end) into `scratch`, the calling
  /// thread's own buffer, reused chunk after chunk.
  std::pair<const std::uint32_t*, std::size_t> select_chunk(const Particles& p, const NeighbourList& list,
                                                            std::size_t i_begin, std::size_t i_end, std::size_t ahead_limit,
                                                            std::vector<std::uint32_t>& scratch) const {
    const std::size_t s_begin = list.begin(i_begin), s_end = list.begin(i_end);
    if (scratch.size() < s_end - s_begin) scratch.resize(s_end - s_begin);
    law_.skip(s_begin, s_end);
    return {scratch.data(), p.n_mobile >= pair_loop::kPrefetchFromBalls
                                ? select_interacting<true>(p, list, s_begin, s_end, ahead_limit, scratch.data())
                                : select_interacting<false>(p, list, s_begin, s_end, ahead_limit, scratch.data())};
  }

  /// The pass over the selected slots of a chunk of balls ending at i_end: each pair adds to its
  /// owner and scatters its reaction onto balls below scatter_end. A pair reaching a mobile ball
  /// at or beyond scatter_end adds to its owner only (that ball's thread computes it itself); a
  /// pair with a wall ball there is stored for the wall's gather.
  template <bool OneThread>
  void chunk_pass(Particles& p, const NeighbourList& list, std::size_t i_end, std::size_t scatter_end,
                  std::pair<const std::uint32_t*, std::size_t> selected, pair_loop::ChunkTotals& ct) const {
    for (std::size_t q = 0; q < selected.second; ++q) {
      const std::size_t s = selected.first[q];
      const std::uint32_t i = list.owner(s), j = list.neighbour(s);
      const bool inward = j < i_end;
      const Result r = law_.template evaluate<true>(p, s, i, j, inward ? ct.in : ct.out, inward ? ct.om_in : ct.om_out);
      p.f[i] += r.f;
      if constexpr (kTorques) p.t[i] += r.torque_i;
      if (OneThread || j < scatter_end) {
        p.f[j] -= r.f;  // (3): the reaction
        if constexpr (kTorques) p.t[j] += r.torque_j;
      } else if (j >= p.n_mobile) {
        pair_f_[s] = r.f, stored_in_[s] = call_;
        if constexpr (kTorques) pair_t_[s] = r.torque_j;
      }
    }
  }

  template <bool OneThread>
  ForceTotals compute_with(Particles& p, const NeighbourList& list) const {
    const std::size_t n = p.size(), nm = p.n_mobile, size = pair_loop::kChunk, chunks = (nm + size - 1) / size;
    partial_.assign(chunks, pair_loop::ChunkTotals{});
    if (selected_.size() < std::size_t(threads())) selected_.resize(std::size_t(threads()));
    const auto chunk_end = [&](std::size_t c) { return std::min(nm, (c + 1) * size); };
    const auto pass = [&](std::size_t c, std::size_t scatter_end, int t) {
      pair_loop::ChunkTotals ct;  // a local, kept in registers, stored once per chunk
      chunk_pass<OneThread>(p, list, chunk_end(c), scatter_end,
                            select_chunk(p, list, c * size, chunk_end(c), std::min(nm, scatter_end) - 1,
                                         selected_[std::size_t(t)]),
                            ct);
      partial_[c] = ct;
    };
    if constexpr (OneThread) {
      for (std::size_t j = 0; j < n; ++j) p.f[j] = Vec3::Zero();
      if constexpr (kTorques)
        for (std::size_t j = 0; j < n; ++j) p.t[j] = Vec3::Zero();
      for (std::size_t c = 0; c < chunks; ++c) pass(c, n, 0);
    } else {
      threaded_pass(p, list, chunks, pass);
    }
    if constexpr (!OneThread) balance_shares();
    return sum_partials();
  }

  /// The chunks' energy terms in chunk order: outward pairs, then inward.
  ForceTotals sum_partials() const {
    ForceTotals t;
    for (const pair_loop::ChunkTotals& c : partial_)
      for (const ForceTotals* q : {&c.out, &c.in}) {
        t.elastic_contact += q->elastic_contact;
        t.elastic_cohesion += q->elastic_cohesion;
        t.p_dissipated += q->p_dissipated;
        t.p_cohesion += q->p_cohesion;
        t.elastic_tangential += q->elastic_tangential;
        t.elastic_rolling += q->elastic_rolling;
        t.p_friction += q->p_friction;
        t.contacts += q->contacts;
        t.sliding += q->sliding;
      }
    for (const pair_loop::ChunkTotals& c : partial_)
      t.max_overlap_ratio = std::max({t.max_overlap_ratio, c.om_out.ratio(), c.om_in.ratio()});
    return t;
  }

  /// One process's share of a partitioned scene (core/partition.hpp), on one thread. First the
  /// pairs of the lower ghosts: the reactions they put on owned balls come first in those balls'
  /// sums, as on one process, and the contact history of those pairs must move on here too. The
  /// ghosts' own forces stay incomplete (their owners compute them) and their energy is not
  /// booked. Then the owned balls' chunks, whose energy terms are joined with the other
  /// processes' in chunk order. The walls' reactions are stored per slot for finish_walls.
  ForceTotals compute_share(Particles& p, const NeighbourList& list, const Partition& part) const {
    const std::size_t n = p.size(), nm = p.n_mobile, b = part.own_begin, e = part.own_end, size = pair_loop::kChunk;
    for (std::size_t j = 0; j < n; ++j) zero_ball(p, j);
    if (selected_.empty()) selected_.resize(1);
    for (std::size_t lo = 0; lo < b; lo += size) {
      const auto sel = select_chunk(p, list, lo, std::min(b, lo + size), nm - 1, selected_[0]);
      pair_loop::ChunkTotals unused;
      for (std::size_t q = 0; q < sel.second; ++q) {
        const std::size_t s = sel.first[q];
        const std::uint32_t i = list.owner(s), j = list.neighbour(s);
        const Result r = law_.template evaluate<true>(p, s, i, j, unused.in, unused.om_in);
        p.f[i] += r.f;
        if constexpr (kTorques) p.t[i] += r.torque_i;
        if (j < nm) {
          p.f[j] -= r.f;
          if constexpr (kTorques) p.t[j] += r.torque_j;
        }
      }
    }
    pair_f_.resize(list.pair_count());
    if constexpr (kTorques) pair_t_.resize(list.pair_count());
    stored_in_.resize(list.pair_count(), 0);
    if (++call_ == 0) std::fill(stored_in_.begin(), stored_in_.end(), 0u), call_ = 1;
    const std::size_t chunks = (e - b + size - 1) / size;
    partial_.assign(chunks, pair_loop::ChunkTotals{});
    for (std::size_t c = 0; c < chunks; ++c) {
      const std::size_t i_begin = b + c * size, i_end = std::min(e, i_begin + size);
      chunk_pass<false>(p, list, i_end, nm, select_chunk(p, list, i_begin, i_end, nm - 1, selected_[0]), partial_[c]);
    }
    partial_ = part.gather_values(partial_);
    return sum_partials();
  }

  /// The walls' loads of the last evaluation of a partitioned scene: each wall sums its stored
  /// reactions rank after rank, in slot order (Partition::chain). Only when a load is read (a
  /// series row, the end): a pass over every wall and a message through every process.
  void finish_walls(Particles& p, const NeighbourList& list) const override {
    const Partition* part = partition();
    if (!part) return;
    const std::size_t n = p.size(), nm = p.n_mobile;
    std::vector<double> walls(6 * (n - nm), 0.0);
    part->chain(walls, [&](std::vector<double>& w) {
      for (std::size_t j = nm; j < n; ++j) {
        double* fj = &w[6 * (j - nm)];
        Vec3 f(fj[0], fj[1], fj[2]), torque(fj[3], fj[4], fj[5]);
        for (std::size_t k = list.reverse_begin(j); k < list.reverse_end(j); ++k) {
          const std::size_t s = list.reverse_slot(k);
          if (stored_in_[s] != call_) continue;
          f -= pair_f_[s];
          if constexpr (kTorques) torque += pair_t_[s];
        }
        for (int d = 0; d < 3; ++d) fj[d] = f[d], fj[3 + d] = torque[d];
      }
    });
    for (std::size_t j = nm; j < n; ++j) {
      const double* fj = &walls[6 * (j - nm)];
      p.f[j] = Vec3(fj[0], fj[1], fj[2]);
      if constexpr (kTorques) p.t[j] = Vec3(fj[3], fj[4], fj[5]);
    }
  }

  template <class Pass>
  void threaded_pass(Particles& p, const NeighbourList& list, std::size_t chunks, const Pass& pass) const {
    const std::size_t n = p.size(), nm = p.n_mobile, size = pair_loop::kChunk;
    pair_f_.resize(list.pair_count());
    if constexpr (kTorques) pair_t_.resize(list.pair_count());
    // A stored force is marked with the call that stored it; clearing every wall slot each call
    // instead cost about a sixth of the threaded loop.
    stored_in_.resize(list.pair_count(), 0);
    if (++call_ == 0) std::fill(stored_in_.begin(), stored_in_.end(), 0u), call_ = 1;
    const int team_size = threads();
    if (share_.size() != std::size_t(team_size)) share_.assign(std::size_t(team_size), 1.0 / team_size);
    seconds_.assign(std::size_t(team_size), 0.0);
    slots_.assign(std::size_t(team_size), 0);
    spanning_.resize(std::size_t(team_size));
    parallel_team([&](int t, int team) {
      const auto start = std::chrono::steady_clock::now();
      // Ranges at chunk edges holding the threads' shares of the list slots (balance_shares).
      const auto first_chunk = [&](int k) {
        double before = 0.0;
        for (int q = 0; q < k; ++q) before += share_[std::size_t(q)];
        const std::size_t target = std::size_t(double(list.pair_count()) * before);
        std::size_t c = 0;
        while (c < chunks && list.begin(c * size) < target) ++c;
        return k == team ? chunks : c;
      };
      const std::size_t c_begin = first_chunk(t), c_end = first_chunk(t + 1);
      const std::size_t b = std::min(nm, c_begin * size), e = std::min(nm, c_end * size);
      gather_lower(p, list, b, e);
      for (std::size_t c = c_begin; c < c_end; ++c) pass(c, e, t);
      // A wall is gathered by the thread that stored its last pair: at once if it stored all of
      // them (they are in its cache, and this work counts in the time the ranges balance), after
      // the barrier if a lower range stored some. A wall with no pairs is zeroed by thread 0.
      const std::size_t own_from = list.begin(b), own_to = list.begin(e);
      // Filled as a local and swapped back: the threads' vector headers share a cache line.
      std::vector<std::uint32_t> spanning;
      spanning.swap(spanning_[std::size_t(t)]);
      spanning.clear();
      for (std::size_t j = nm; j < n; ++j) {
        const std::size_t k0 = list.reverse_begin(j), k1 = list.reverse_end(j);
        if (k0 == k1) {
          if (t == 0) zero_ball(p, j);
          continue;
        }
        const std::size_t last = list.reverse_slot(k1 - 1);
        if (last < own_from || last >= own_to) continue;
        if (list.reverse_slot(k0) >= own_from)
          gather_wall(p, list, j);
        else
          spanning.push_back(std::uint32_t(j));
      }
      seconds_[std::size_t(t)] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      slots_[std::size_t(t)] = list.begin(e) - list.begin(b);
      team_barrier();  // every wall reaction is stored before a spanning wall is gathered
      for (const std::uint32_t j : spanning) gather_wall(p, list, j);
      spanning_[std::size_t(t)].swap(spanning);
    });
  }

  /// The reactions from lower ranges come first in every ball's one-thread sum: each ball of
  /// [b, e) starts from them, computed here (the owner's thread computes the same bits).
  void gather_lower(Particles& p, const NeighbourList& list, std::size_t b, std::size_t e) const {
    const std::size_t lower_slots = list.begin(b);
    for (std::size_t j = b; j < e; ++j) {
      Vec3 f = Vec3::Zero(), torque = Vec3::Zero();
      for (std::size_t k = list.reverse_begin(j); k < list.reverse_end(j) && list.reverse_slot(k) < lower_slots; ++k) {
        const std::size_t s = list.reverse_slot(k);
        ForceTotals unused;  // booked by the owner's chunk
        OverlapMax unused_om;
        const Result r = law_.template evaluate<false>(p, s, list.owner(s), std::uint32_t(j), unused, unused_om);
        f -= r.f;
        if constexpr (kTorques) torque += r.torque_j;
      }
      p.f[j] = f;
      if constexpr (kTorques) p.t[j] = torque;
    }
  }

  void gather_wall(Particles& p, const NeighbourList& list, std::size_t j) const {
    Vec3 f = Vec3::Zero(), torque = Vec3::Zero();
    for (std::size_t k = list.reverse_begin(j); k < list.reverse_end(j); ++k) {
      const std::size_t s = list.reverse_slot(k);
      if (stored_in_[s] != call_) continue;  // the pair did not interact
      f -= pair_f_[s];
      if constexpr (kTorques) torque += pair_t_[s];
    }
    p.f[j] = f;
    if constexpr (kTorques) p.t[j] = torque;
  }

  static void zero_ball(Particles& p, std::size_t j) {
    p.f[j] = Vec3::Zero();
    if constexpr (kTorques) p.t[j] = Vec3::Zero();
  }

  /// Moves the threads' shares of the slots toward what each did per second in this call: the
  /// cores of a VM often do not run alike, and with equal shares the faster waits at the barrier.
  /// Only where the ranges meet changes, never a result. Smoothed, so one descheduled step does
  /// not swing the split. A thread left with no slots gives no rate to learn from: the shares
  /// start over equal, so a thread can never be shut out for good.
  void balance_shares() const {
    double total = 0.0;
    std::array<double, 64> rate{};
    if (share_.size() > rate.size()) return;
    for (std::size_t k = 0; k < share_.size(); ++k) {
      if (!(seconds_[k] > 0.0) || slots_[k] == 0) {
        share_.assign(share_.size(), 1.0 / double(share_.size()));
        return;
      }
      rate[k] = double(slots_[k]) / seconds_[k];
      total += rate[k];
    }
    for (std::size_t k = 0; k < share_.size(); ++k) share_[k] = 0.8 * share_[k] + 0.2 * rate[k] / total;
  }

  Law law_;
  mutable std::vector<Vec3> pair_f_, pair_t_;     // per wall slot: force on its owner, torque on the wall (threads > 1)
  mutable std::vector<std::uint32_t> stored_in_;  // per wall slot: the call that stored pair_f_ there
  mutable std::uint32_t call_ = 0;                // threaded calls so far
  mutable std::vector<double> share_, seconds_;   // per thread: its share of the slots, its last pass time
  mutable std::vector<std::size_t> slots_;        // per thread: the slots of its last range
  mutable std::vector<std::vector<std::uint32_t>> spanning_;  // per thread: walls it gathers after the barrier
  mutable std::vector<pair_loop::ChunkTotals> partial_;       // per chunk of kChunk mobile balls
  mutable std::vector<std::vector<std::uint32_t>> selected_;  // per thread: the selected slots of one chunk
};

}  // namespace silodem
