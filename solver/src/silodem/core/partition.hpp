#pragma once
// A process's share of the mobile balls when several processes run one scene (mpi/domain.hpp,
// docs/domain-decomposition.md). Its balls are a contiguous range of the global ball order, held
// between the ghosts of lower and higher ranges; the loops that sum over balls or pairs sum over
// that range only, per chunk as on one process, and join the chunks of all processes in order.
// Without one (partition() is null, every ordinary run) nothing changes: one branch per sum.
#include <cstddef>
#include <cstring>
#include <functional>
#include <vector>

namespace silodem {

class Partition {
 public:
  virtual ~Partition() = default;
  /// Local indices [own_begin, own_end) of the mobile balls this process owns. Below them are the
  /// ghosts of lower ranges, above them those of higher ranges, and last the wall balls (every
  /// process holds all of them).
  std::size_t own_begin = 0, own_end = 0;
  /// Every process's bytes, in rank order (which is the global ball order), on every process.
  virtual std::vector<std::vector<char>> gather_all(const void* data, std::size_t bytes) const = 0;
  /// Passes `values` from rank to rank in order: each process starts from its predecessor's values
  /// (rank 0 from its own), applies `fold` and passes them on; the last rank's result reaches all.
  /// How a sum whose terms lie on several processes keeps the one-process order of additions.
  virtual void chain(std::vector<double>& values, const std::function<void(std::vector<double>&)>& fold) const = 0;

  /// gather_all of one value per process, in rank order.
  template <class T>
  std::vector<T> gather_values(const std::vector<T>& mine) const {
    std::vector<T> all;
    for (const auto& piece : gather_all(mine.data(), mine.size() * sizeof(T))) {
      const std::size_t n = piece.size() / sizeof(T);
      all.resize(all.size() + n);
      if (n) std::memcpy(all.data() + all.size() - n, piece.data(), n * sizeof(T));
    }
    return all;
  }
};

namespace detail {
inline const Partition* g_partition = nullptr;
}  // namespace detail

/// The partition of this process's scene, or null when one process holds every ball.
inline const Partition* partition() { return detail::g_partition; }
inline void set_partition(const Partition* p) { detail::g_partition = p; }

/// The mobile balls this process answers for: its share, or all n_mobile of them.
struct BallRange {
  std::size_t begin, end;
};
inline BallRange owned_mobile(std::size_t n_mobile) {
  const Partition* p = partition();
  return p ? BallRange{p->own_begin, p->own_end} : BallRange{0, n_mobile};
}

}  // namespace silodem
