#pragma once
// Threads (issue 5, "multi-threading of the force and integration loops"; issue 6, determinism).
// Every parallel loop here writes per-ball or per-pair results only and every sum over balls or
// pairs runs in a fixed order after it, so a run is bitwise identical for any thread count.
// Without OpenMP (a compiler that lacks it) the pragmas vanish and everything runs on one thread.
#include <cstddef>

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
