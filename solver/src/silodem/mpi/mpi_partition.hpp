#pragma once
// The partition of core/partition.hpp over MPI_COMM_WORLD: the collective calls the solver's sums
// need, and nothing else MPI-specific leaves this folder.
#include <cstdint>
#include <vector>

#include "silodem/core/partition.hpp"

namespace silodem::mpi {

class MpiPartition final : public Partition {
 public:
  MpiPartition();
  int rank() const { return rank_; }
  int ranks() const { return ranks_; }
  std::vector<std::vector<char>> gather_all(const void* data, std::size_t bytes) const override;
  void chain(std::vector<double>& values, const std::function<void(std::vector<double>&)>& fold) const override;
  /// Each process's `to[q]` reaches process q, which gets them in rank order (the empty ones too).
  /// `sizes`, if the receiver knows them: the bytes it gets from each process (saves a round of messages).
  std::vector<std::vector<char>> exchange(const std::vector<std::vector<char>>& to,
                                          const std::vector<std::size_t>* sizes = nullptr) const;
  /// The largest of every process's value.
  double max_all(double mine) const;
  /// Rank 0's bytes on every process.
  std::vector<char> from_rank0(std::vector<char> bytes) const;

 private:
  int rank_ = 0, ranks_ = 1;
};

}  // namespace silodem::mpi
