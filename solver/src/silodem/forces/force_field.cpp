#include "silodem/forces/force_field.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "silodem/contact/contact_law.hpp"
#include "silodem/contact/pair_constants.hpp"
#include "silodem/core/parallel.hpp"

namespace silodem {

namespace {

/// Dashpot scale in the step next to first touch (δ̇ > 0) or, unclamped, to separation (δ̇ < 0):
/// the contact fills only a fraction θ of the interval next to this step, but the trapezoid
/// impulse of every scheme here — ½Δt (F_n−1 + F_n) — books the jump of the dashpot force c δ̇ over
/// half an interval. Scaling the dashpot by θ + ½ in that one step gives the interval the impulse
/// c δ̇ θ Δt: the O(ζ ω Δt) error in e becomes O((ω Δt)²). Both balls get the same scaled force, so
/// momentum is conserved. Touch: θ = δ/(δ̇ Δt) < 1, the overlap one step's approach makes (a
/// quadratic in the deceleration was tried: 10× larger errors at ζ = 0.9, t_c/50). Separation:
/// θΔt is the root of δ + δ̇ τ + ½ δ̈ τ² = 0 with δ̈ = −f/m_eff, since the unclamped tensile dashpot
/// slows the parting and the linear guess would fire in several steps. A clamped law's force goes
/// to zero continuously before separation (a kink, not a jump): left alone there.
template <bool Clamp>
inline double onset_scale(double delta, double delta_rate, double dt, double f, double inv_m_eff) {
  // θ = 1 up to rounding is a touch exactly on the previous step (δ was 0 there, no force yet).
  // Without a branch on the data: about half the contacts of a dense bed approach, in an order no
  // branch predictor learns (a branch here cost the dense bed +60 % per step). With δ̇ ≤ 0 the
  // quotient is ±inf or negative and the select drops it.
  const double step_approach = delta_rate * dt;
  const double touch_scale = 0.5 + delta / step_approach;
  const bool touched = (delta_rate > 0.0) & (delta < step_approach * (1.0 + 1e-9));
  const double scale = touched ? touch_scale : 1.0;
  if (Clamp || delta_rate >= 0.0) return scale;
  const double a = -0.5 * f * inv_m_eff, b = delta_rate, c = delta;  // a τ² + b τ + c = 0, b < 0 < c
  const double disc = b * b - 4.0 * a * c;
  if (disc < 0.0) return 1.0;  // the tensile force stops the parting first
  const double tau = 2.0 * c / (-b + std::sqrt(disc));  // the smaller positive root, stable form
  return tau < dt ? 0.5 + tau / dt : 1.0;
}

/// Balls per chunk of the force loop: the unit of its energy sums (the same chunks on any thread
/// count, so the same bits) and of its selection pass, and the step in which threads' ranges
/// move. Small, so that the ranges can balance finely: on the 5,000-ball anchor bed 256 gives 20
/// chunks.
constexpr std::size_t kForceChunk = 256;

/// How far ahead of the owner the loop prefetches: one sweep front and a margin. Capped so that
/// what is fetched early still fits the last-level cache when the order has decayed (balls mixing
/// between renumberings) and the front is long.
constexpr std::size_t kAheadMargin = 64, kMaxAhead = 16384;

/// Below this many mobile balls the loop's data (about 350 bytes a ball with its list) fits this
/// VM's last-level cache and there is nothing to hide: the loop is left exactly as it was. Measured
/// (reports/perf_experiments.md): 300,000 balls tiled, 8 % faster with the prefetch; 100,000, no
/// slower; 20,000, within this host's noise either way (3 interleaved runs: 6.13-8.34 s with it,
/// 5.84-7.97 s without) — no gain shown there, hence off.
constexpr std::size_t kPrefetchFromBalls = 50000;

template <bool Cohesion, bool Clamp, bool Onset>
class KelvinVoigtField final : public ForceField {
 public:
  KelvinVoigtField(double p_n, double g_abs, double dt) : pn_g_(p_n * g_abs), dt_(dt) {}

  // One thread: a single pass in ball order — ball i starts from the reactions of the pairs of
  // lower balls (already scattered onto it), adds the pairs it owns and scatters their reactions.
  // More threads: each takes one run of consecutive balls (a range of whole chunks) and does the
  // same inside it. A ball first gathers the reactions of the pairs it has with balls of lower
  // ranges, computing those pairs itself (their owners compute them too, for their own force: the
  // same bits), so no thread waits for another; pairs reaching a higher range add only to their
  // owner; pairs with walls are stored, and each wall sums its stored reactions, in slot order, on
  // the thread that stored its last one: right after that thread's range if it stored them all,
  // after one barrier if a lower range stored some. Every ball's force is the same sum in the same
  // order as on one thread: the same bits for any thread count (core/parallel.hpp). Energy terms are summed per chunk of kForceChunk
  // balls — outward pairs, then inward pairs, each in slot order — then over chunks in order, on
  // either path. A chunk first selects its interacting pairs (select_interacting), then runs the
  // law on those alone, in slot order: the same sums as a pass over every slot.
  ForceTotals compute(Particles& p, const NeighbourList& list) const override {
    return threads() == 1 ? compute_with<true>(p, list) : compute_with<false>(p, list);
  }

  std::size_t bytes() const override {
    std::size_t b = heap_bytes(pair_f_) + heap_bytes(stored_in_) + heap_bytes(partial_);
    for (const auto& w : spanning_) b += heap_bytes(w);
    for (const auto& w : selected_) b += heap_bytes(w);
    return b;
  }

 private:
  /// Running maximum of δ / min(r_i, r_j) kept as the fraction itself: comparing δ_a r_b > δ_b r_a
  /// needs no division per contact.
  struct OverlapMax {
    double delta = 0.0, r = 1.0;
    void take(double d, double r_min) {
      if (d * r > delta * r_min) delta = d, r = r_min;
    }
    double ratio() const { return delta / r; }
  };

  /// What the pairs of one chunk add to the totals: outward (neighbour beyond the chunk) and inward.
  struct ChunkTotals {
    ForceTotals out, in;
    OverlapMax om_out, om_in;
  };

  /// The slots in [s_begin, s_end) whose balls can interact now, in slot order, into `out`. No
  /// branch on the data: about half the listed pairs of a dense bed touch, in an order no branch
  /// predictor learns, and a mispredicted branch per pair stalls the long sqrt–divide chain of
  /// the law; the pairs that pass then go through the law back to back. Without cohesion the test
  /// is pair_force's own; with it, a distance bound beyond the law's. Either way a pair left out is
  /// one the law would have given zero.
  template <bool Prefetch>
  std::size_t select_interacting(const Particles& p, const NeighbourList& list, std::size_t s_begin, std::size_t s_end,
                                 std::size_t ahead_limit, std::uint32_t* out) const {
    const std::size_t ahead = std::min(list.front(), kMaxAhead) + kAheadMargin;
    AheadHints hints(p);
    std::size_t n = 0;
    // One flat run of slots: a loop per ball and its few slots was 8 % slower on the 20,000-ball
    // bed (likely its exit branch after 0-8 slots, once per ball; not measured apart).
    for (std::size_t s = s_begin; s < s_end; ++s) {
      out[n] = std::uint32_t(s);
      const std::uint32_t i = list.owner(s), j = list.neighbour(s);
      if constexpr (Prefetch) hints.next(std::min(i + ahead, ahead_limit));  // once per slot: no branch
      if constexpr (Cohesion) {
        // The cohesion zone reaches |δ_c| ≤ list.reach() beyond touching (10): a pair farther
        // apart gets no force. The margin keeps a pair exactly at the reach, which the law
        // still pulls (δ = δ_c), whatever the rounding of the distance.
        const double cut = p.r[i] + p.r[j] + list.reach() * (1.0 + 1e-9) + 1e-15;
        n += std::size_t((p.x[i] - p.x[j]).squaredNorm() < cut * cut);
      } else {
        const double touch = p.r[i] + p.r[j];
        n += std::size_t((p.x[i] - p.x[j]).squaredNorm() < touch * touch);
      }
    }
    return n;
  }

  /// Asks, one hint per call, for the lines of a ball that the loop will read before it does. A
  /// ball's data is first read when it is the farthest partner of a ball one sweep front
  /// (list.front()) below it, in no order the hardware prefetcher follows across the arrays: at
  /// 10^5-10^6 balls (data in memory, not cache) those loads stalled the loop. The hints rotate
  /// through the arrays in rounds of eight slots, x twice (the selection pass reads it first);
  /// at about 4.6 slots per ball a 24-byte array is asked for every 1.7 balls, and its lines hold
  /// 2.7. All six or seven arrays at every slot (the loop until the tenth session) made the force
  /// loop 3-6 % slower at 10^5 (interleaved runs) and, with cold caches at 5,000 balls, hid less
  /// of the misses (reports/perf_experiments.md): the hints themselves cost issue slots. Read hints
  /// only: with threads, the lines past a range belong to a thread that writes their forces.
  class AheadHints {
   public:
    explicit AheadHints(const Particles& p)
        : round_{of(p.x), of(p.f), of(p.v), of(p.x), of(p.r), of(p.k), of(p.c), Cohesion || Onset ? of(p.m) : of(p.f)} {}
    void next(std::size_t ball) {
      __builtin_prefetch(round_[at_].base + ball * round_[at_].stride);
      at_ = (at_ + 1) & 7u;
    }

   private:
    struct Array {
      const char* base;
      std::size_t stride;
    };
    template <class T>
    static Array of(const std::vector<T>& a) { return {reinterpret_cast<const char*>(a.data()), sizeof(T)}; }
    Array round_[8];
    unsigned at_ = 0;
  };

  /// Selects the interacting slots of the balls [i_begin, i_end) into `scratch`, the calling
  /// thread's own buffer (select_interacting); returns where they start and how many there are.
  /// One chunk's worth, reused: 4 bytes per listed pair fewer than a slot-sized array (no
  /// measurable change in speed).
  std::pair<const std::uint32_t*, std::size_t> select_chunk(const Particles& p, const NeighbourList& list,
                                                            std::size_t i_begin, std::size_t i_end, std::size_t ahead_limit,
                                                            std::vector<std::uint32_t>& scratch) const {
    const std::size_t s_begin = list.begin(i_begin), s_end = list.begin(i_end);
    if (scratch.size() < s_end - s_begin) scratch.resize(s_end - s_begin);
    return {scratch.data(), p.n_mobile >= kPrefetchFromBalls
                                ? select_interacting<true>(p, list, s_begin, s_end, ahead_limit, scratch.data())
                                : select_interacting<false>(p, list, s_begin, s_end, ahead_limit, scratch.data())};
  }

  /// The one-thread pass over the selected slots of a chunk of balls ending at i_end: each ball
  /// starts from the reactions already on it, adds its pairs and scatters their reactions onto
  /// balls below scatter_end. A pair reaching a mobile ball at or beyond scatter_end adds to its
  /// owner only (that ball's thread computes it itself); a pair with a wall ball there is stored
  /// for the wall's gather. Every p.f sees the same additions in the same order as a loop over
  /// the balls and their slots.
  template <bool OneThread>
  void chunk_pass(Particles& p, const NeighbourList& list, std::size_t i_end, std::size_t scatter_end,
                  std::pair<const std::uint32_t*, std::size_t> selected, ChunkTotals& ct) const {
    for (std::size_t q = 0; q < selected.second; ++q) {
      const std::size_t s = selected.first[q];
      const std::uint32_t i = list.owner(s), j = list.neighbour(s);
      const bool inward = j < i_end;
      const Vec3 fij = pair_force(p, i, j, p.x[i], p.v[i], p.r[i], inward ? ct.in : ct.out,
                                  inward ? ct.om_in : ct.om_out);  // (3): opposite on j
      p.f[i] += fij;
      if (OneThread || j < scatter_end)
        p.f[j] -= fij;
      else if (j >= p.n_mobile)
        pair_f_[s] = fij, stored_in_[s] = call_;
    }
  }

  template <bool OneThread>
  ForceTotals compute_with(Particles& p, const NeighbourList& list) const {
    const std::size_t n = p.size(), nm = p.n_mobile, size = kForceChunk, chunks = (nm + size - 1) / size;
    partial_.assign(chunks, ChunkTotals{});
    if (selected_.size() < std::size_t(threads())) selected_.resize(std::size_t(threads()));
    const auto chunk_end = [&](std::size_t c) { return std::min(nm, (c + 1) * size); };
    const auto pass = [&](std::size_t c, std::size_t scatter_end, int t) {
      ChunkTotals ct;  // a local, kept in registers, stored once per chunk
      chunk_pass<OneThread>(p, list, chunk_end(c), scatter_end,
                            select_chunk(p, list, c * size, chunk_end(c), std::min(nm, scatter_end) - 1,
                                         selected_[std::size_t(t)]),
                            ct);
      partial_[c] = ct;
    };
    if constexpr (OneThread) {
      for (std::size_t j = 0; j < n; ++j) p.f[j] = Vec3::Zero();
      for (std::size_t c = 0; c < chunks; ++c) pass(c, n, 0);
    } else {
      pair_f_.resize(list.pair_count());
      // A stored force is marked with the call that stored it; clearing every wall slot each
      // call instead cost about a sixth of the threaded loop.
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
        // The reactions from lower ranges come first in every ball's one-thread sum.
        const std::size_t lower_slots = list.begin(b);
        for (std::size_t j = b; j < e; ++j) {
          Vec3 f = Vec3::Zero();
          for (std::size_t k = list.reverse_begin(j); k < list.reverse_end(j) && list.reverse_slot(k) < lower_slots; ++k) {
            const std::size_t s = list.reverse_slot(k);
            ForceTotals unused;  // booked by the owner's chunk
            OverlapMax unused_om;
            const std::uint32_t i = list.owner(s);
            f -= pair_force(p, i, std::uint32_t(j), p.x[i], p.v[i], p.r[i], unused, unused_om);
          }
          p.f[j] = f;
        }
        for (std::size_t c = c_begin; c < c_end; ++c) pass(c, e, t);
        // A wall is gathered by the thread that stored its last pair: at once if it stored all of
        // them (they are in its cache, and this work counts in the time the ranges balance), after
        // the barrier if a lower range stored some. A wall with no pairs is zeroed by thread 0.
        const std::size_t own_from = list.begin(b), own_to = list.begin(e);
        // Filled as a local and swapped back: the threads' vector headers share a cache line.
        std::vector<std::uint32_t> spanning;
        spanning.swap(spanning_[std::size_t(t)]);
        spanning.clear();
        const auto gather_wall = [&](std::size_t j) {
          Vec3 f = Vec3::Zero();
          for (std::size_t k = list.reverse_begin(j); k < list.reverse_end(j); ++k) {
            const std::size_t s = list.reverse_slot(k);
            if (stored_in_[s] == call_) f -= pair_f_[s];  // else the pair did not interact
          }
          p.f[j] = f;
        };
        for (std::size_t j = nm; j < n; ++j) {
          const std::size_t k0 = list.reverse_begin(j), k1 = list.reverse_end(j);
          if (k0 == k1) {
            if (t == 0) p.f[j] = Vec3::Zero();
            continue;
          }
          const std::size_t last = list.reverse_slot(k1 - 1);
          if (last < own_from || last >= own_to) continue;
          if (list.reverse_slot(k0) >= own_from)
            gather_wall(j);
          else
            spanning.push_back(std::uint32_t(j));
        }
        seconds_[std::size_t(t)] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        slots_[std::size_t(t)] = list.begin(e) - list.begin(b);
        team_barrier();  // every wall reaction is stored before a spanning wall is gathered
        for (const std::uint32_t j : spanning) gather_wall(j);
        spanning_[std::size_t(t)].swap(spanning);
      });
    }
    if constexpr (!OneThread) balance_shares();
    ForceTotals t;
    for (const ChunkTotals& c : partial_)
      for (const ForceTotals* q : {&c.out, &c.in}) {
        t.elastic_contact += q->elastic_contact;
        t.elastic_cohesion += q->elastic_cohesion;
        t.p_dissipated += q->p_dissipated;
        t.p_cohesion += q->p_cohesion;
        t.contacts += q->contacts;
      }
    for (const ChunkTotals& c : partial_)
      t.max_overlap_ratio = std::max({t.max_overlap_ratio, c.om_out.ratio(), c.om_in.ratio()});
    return t;
  }

  /// Moves the threads' shares of the slots toward what each did per second in this call: the
  /// cores of a VM often do not run alike, and with equal shares the faster waits at the barrier.
  /// Only where the ranges meet changes, never a result. Smoothed, so one descheduled step does
  /// not swing the split. A thread left with no slots (shares that a long stall drove below one
  /// chunk, or more threads than chunks) gives no rate to learn from: the shares start over equal,
  /// so a thread can never be shut out for good.
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

  /// The force of the pair (i, j) on i, zero if they do not interact; adds its energy terms to t.
  /// Always inlined: called from inside the threads' lambdas, GCC had kept it out of line (perf).
  [[gnu::always_inline]] Vec3 pair_force(const Particles& p, std::size_t i, std::uint32_t j, const Vec3& xi, const Vec3& vi, double ri,
                  ForceTotals& t, OverlapMax& om) const {
    const Vec3 d = xi - p.x[j];
    const double dist2 = d.squaredNorm();
    const double rj = p.r[j];
    const double touch = ri + rj;
    if (!Cohesion && dist2 >= touch * touch) return Vec3::Zero();
    const double dist = std::sqrt(dist2);
    const double delta = touch - dist;                 // (5)
    const double k = contact::series(p.k[i], p.k[j]);  // (11)
    contact::PairForce pf;
    const Vec3 n = d * (1.0 / dist);                    // (6), from j to i
    const double delta_rate = -(vi - p.v[j]).dot(n);    // dδ/dt, > 0 approaching (docs/model.md §2.2 Reading of (7))
    if (delta > 0.0) {
      double c = contact::series(p.c[i], p.c[j]);
      if constexpr (Onset)
        c *= onset_scale<Clamp>(delta, delta_rate, dt_, k * delta + c * delta_rate,
                                1.0 / p.m[i] + (j < p.n_mobile ? 1.0 / p.m[j] : 0.0));
      pf = contact::kelvin_voigt<Clamp>(k, c, delta, delta_rate);  // (4)
      t.elastic_contact += pf.elastic;
      om.take(delta, std::min(ri, rj));
      ++t.contacts;
    } else if constexpr (Cohesion) {
      const double delta_c = contact::cohesion_reach(1.0, pn_g_, std::min(p.m[i], p.m[j]), k);  // (10)
      if (delta < delta_c) return Vec3::Zero();
      pf = contact::cohesion(k, delta_c, delta, delta_rate);  // (9)
      t.elastic_cohesion += pf.elastic;
      t.p_cohesion += pf.p_cohesion;
    }
    t.p_dissipated += pf.p_dissipated;
    return pf.f * n;
  }

  mutable std::vector<Vec3> pair_f_;          // per wall slot: the force on its owner i (threads > 1)
  mutable std::vector<std::uint32_t> stored_in_;  // per wall slot: the call that stored pair_f_ there
  mutable std::uint32_t call_ = 0;                // threaded calls so far
  mutable std::vector<double> share_, seconds_;     // per thread: its share of the slots, its last pass time
  mutable std::vector<std::size_t> slots_;          // per thread: the slots of its last range
  mutable std::vector<std::vector<std::uint32_t>> spanning_;  // per thread: walls it gathers after the barrier
  mutable std::vector<ChunkTotals> partial_;          // per chunk of kForceChunk mobile balls
  mutable std::vector<std::vector<std::uint32_t>> selected_;  // per thread: select_interacting's, one chunk
  double pn_g_, dt_;
};

template <bool Cohesion, bool Clamp>
std::unique_ptr<ForceField> with_onset(const ContactSpec& spec, double g_abs, double dt) {
  if (spec.onset_correction) return std::make_unique<KelvinVoigtField<Cohesion, Clamp, true>>(spec.p_n, g_abs, dt);
  return std::make_unique<KelvinVoigtField<Cohesion, Clamp, false>>(spec.p_n, g_abs, dt);
}

}  // namespace

std::unique_ptr<ForceField> make_force_field(const ContactSpec& spec, double g_abs, double dt) {
  if (spec.onset_correction && !(dt > 0.0)) throw std::invalid_argument("onset correction needs the time step");
  if (spec.cohesion) return spec.clamp ? with_onset<true, true>(spec, g_abs, dt) : with_onset<true, false>(spec, g_abs, dt);
  return spec.clamp ? with_onset<false, true>(spec, g_abs, dt) : with_onset<false, false>(spec, g_abs, dt);
}

double max_cohesion_reach(const Particles& p, const ContactSpec& spec, double g_abs, double extra_mass_max,
                          double extra_k_min) {
  if (!spec.cohesion) return 0.0;
  // |δ_c| = p_N g min(m)/k_ij grows with mass and falls with stiffness: bound it with the largest
  // mass and the smallest per-ball stiffness present (k_ij ≥ k_min/2).
  double m_max = extra_mass_max, k_min = extra_k_min > 0.0 ? extra_k_min : 1e300;
  for (std::size_t i = 0; i < p.size(); ++i) {
    m_max = std::max(m_max, p.m[i]);
    k_min = std::min(k_min, p.k[i]);
  }
  return spec.p_n * g_abs * m_max / (0.5 * k_min);
}

}  // namespace silodem
