#pragma once
// Threads (issue 5, "multi-threading of the force and integration loops"; issue 6, determinism).
// Every parallel loop here writes per-ball or per-pair results only and every sum over balls or
// pairs runs in a fixed order after it, so a run is bitwise identical for any thread count.
// Without OpenMP (a compiler that lacks it) the pragmas vanish and everything runs on one thread.
#include <atomic>
#include <cstddef>
#include <cstdint>

namespace silodem::detail {
// Our own count, not OpenMP's default (every core): a test or the harness that never asks for
// threads must not spin two threads per process on a machine that runs two such processes.
inline int g_threads = 1;
}  // namespace silodem::detail

#if defined(_OPENMP)
#include <omp.h>
#define SILODEM_PARALLEL_FOR \
  _Pragma("omp parallel for schedule(static) num_threads(::silodem::detail::g_threads) if (::silodem::detail::g_threads > 1)")
// Chunks of uneven work (the neighbour search's balls have different numbers of candidates): handed out
// one at a time. Safe for determinism because each chunk writes only its own results.
#define SILODEM_PARALLEL_FOR_DYNAMIC \
  _Pragma("omp parallel for schedule(dynamic, 1) num_threads(::silodem::detail::g_threads) if (::silodem::detail::g_threads > 1)")
#else
#define SILODEM_PARALLEL_FOR
#define SILODEM_PARALLEL_FOR_DYNAMIC
#endif

namespace silodem {

/// Sums over balls are taken per chunk of this many consecutive balls, then over the chunks in
/// order: the same additions in the same order whatever the thread count or the schedule.
inline constexpr std::size_t kSumChunk = 512;
inline std::size_t sum_chunks(std::size_t n) { return (n + kSumChunk - 1) / kSumChunk; }

/// Threads for the loops above (1 unless set; `run --threads N`).
inline void set_threads(int n) { detail::g_threads = n < 1 ? 1 : n; }

/// Runs f(thread, team size) on every thread of one team (f(0, 1) on one thread). Inside f,
/// team_barrier() waits for the whole team.
template <class F>
void parallel_team(F&& f) {
#if defined(_OPENMP)
  if (detail::g_threads > 1) {
#pragma omp parallel num_threads(detail::g_threads)
    f(omp_get_thread_num(), omp_get_num_threads());
    return;
  }
#endif
  f(0, 1);
}

/// Chunks [0, n) handed to a team of two from opposite ends: thread 0 takes the lowest chunk
/// left, thread 1 the highest, until they meet. Each thread's chunks stay one contiguous run, as
/// with a static split (a chunk's balls stay in one core's cache from pass to pass; chunks dealt
/// one at a time from one end lose that, reports/perf_experiments.md), yet where they meet
/// follows how fast each core actually runs — the two cores of a VM often do not run alike.
/// Chunks are independent, so who does which never changes a result.
class TwoEndedChunks {
 public:
  /// Before the team starts (not from inside it).
  void reset(std::size_t n) { ends_.store(std::uint64_t(n) << 32, std::memory_order_relaxed); }
  /// The next chunk for thread t (0 from the front, 1 from the back); false once none are left.
  bool take(int t, std::size_t& chunk) {
    std::uint64_t cur = ends_.load(std::memory_order_relaxed);
    for (;;) {
      const std::uint64_t lo = cur & 0xffffffffu, hi = cur >> 32;
      if (lo >= hi) return false;
      const std::uint64_t next = t == 0 ? cur + 1 : cur - (std::uint64_t(1) << 32);
      if (ends_.compare_exchange_weak(cur, next, std::memory_order_relaxed)) {
        chunk = std::size_t(t == 0 ? lo : hi - 1);
        return true;
      }
    }
  }

  /// Where the two met: thread 0 did [0, met()), thread 1 the rest (once every chunk is taken).
  std::size_t met() const { return std::size_t(ends_.load(std::memory_order_relaxed) & 0xffffffffu); }

 private:
  std::atomic<std::uint64_t> ends_{0};
};

inline void team_barrier() {
#if defined(_OPENMP)
#pragma omp barrier
#endif
}

inline int threads() {
#if defined(_OPENMP)
  return detail::g_threads;
#else
  return 1;
#endif
}

}  // namespace silodem
