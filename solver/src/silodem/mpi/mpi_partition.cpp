#include "silodem/mpi/mpi_partition.hpp"

#include <mpi.h>

#include <climits>
#include <stdexcept>

namespace silodem::mpi {

namespace {
int as_count(std::size_t n) {
  if (n > std::size_t(INT_MAX)) throw std::runtime_error("an MPI message beyond 2 GiB (more balls on a process than v1 of the decomposition sends at once)");
  return int(n);
}
}  // namespace

MpiPartition::MpiPartition() {
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks_);
}

std::vector<std::vector<char>> MpiPartition::gather_all(const void* data, std::size_t bytes) const {
  const int mine = as_count(bytes);
  const std::size_t r = std::size_t(ranks_);
  std::vector<int> counts(r, 0), displs(r, 0);
  MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  std::size_t total = 0;
  for (int q = 0; q < ranks_; ++q) displs[std::size_t(q)] = as_count(total), total += std::size_t(counts[std::size_t(q)]);
  std::vector<char> all(total);
  MPI_Allgatherv(data, mine, MPI_BYTE, all.data(), counts.data(), displs.data(), MPI_BYTE, MPI_COMM_WORLD);
  std::vector<std::vector<char>> pieces(r);
  for (int q = 0; q < ranks_; ++q) {
    const auto b = all.begin() + displs[std::size_t(q)];
    pieces[std::size_t(q)].assign(b, b + counts[std::size_t(q)]);
  }
  return pieces;
}

void MpiPartition::chain(std::vector<double>& values, const std::function<void(std::vector<double>&)>& fold) const {
  const int n = as_count(values.size());
  if (rank_ > 0) MPI_Recv(values.data(), n, MPI_DOUBLE, rank_ - 1, 7, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  fold(values);
  if (rank_ + 1 < ranks_) MPI_Send(values.data(), n, MPI_DOUBLE, rank_ + 1, 7, MPI_COMM_WORLD);
  MPI_Bcast(values.data(), n, MPI_DOUBLE, ranks_ - 1, MPI_COMM_WORLD);
}

std::vector<std::vector<char>> MpiPartition::exchange(const std::vector<std::vector<char>>& to,
                                                     const std::vector<std::size_t>* sizes) const {
  const std::size_t r = std::size_t(ranks_);
  std::vector<int> send_counts(r), send_displs(r), recv_counts(r), recv_displs(r);
  std::vector<char> send;
  for (std::size_t q = 0; q < r; ++q) {
    send_displs[q] = as_count(send.size());
    send_counts[q] = as_count(to[q].size());
    send.insert(send.end(), to[q].begin(), to[q].end());
  }
  if (sizes)
    for (std::size_t q = 0; q < r; ++q) recv_counts[q] = as_count((*sizes)[q]);
  else
    MPI_Alltoall(send_counts.data(), 1, MPI_INT, recv_counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  std::size_t total = 0;
  for (std::size_t q = 0; q < r; ++q) recv_displs[q] = as_count(total), total += std::size_t(recv_counts[q]);
  std::vector<char> recv(total);
  MPI_Alltoallv(send.data(), send_counts.data(), send_displs.data(), MPI_BYTE, recv.data(), recv_counts.data(),
                recv_displs.data(), MPI_BYTE, MPI_COMM_WORLD);
  std::vector<std::vector<char>> from(r);
  for (std::size_t q = 0; q < r; ++q) from[q].assign(recv.begin() + recv_displs[q], recv.begin() + recv_displs[q] + recv_counts[q]);
  return from;
}

double MpiPartition::max_all(double mine) const {
  double all = 0.0;
  MPI_Allreduce(&mine, &all, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return all;
}

std::vector<char> MpiPartition::from_rank0(std::vector<char> bytes) const {
  unsigned long long n = bytes.size();
  MPI_Bcast(&n, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
  bytes.resize(std::size_t(n));
  MPI_Bcast(bytes.data(), as_count(bytes.size()), MPI_BYTE, 0, MPI_COMM_WORLD);
  return bytes;
}

}  // namespace silodem::mpi
