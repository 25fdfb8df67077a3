#pragma once
// The two largest of a set of values (squared displacements): the neighbour list's rebuild test
// and the MPI ghosts' margin test (mpi/domain.cpp) both bound how far two balls can have closed
// by the two largest displacements. Mergeable across threads and processes.
namespace silodem {

struct TwoLargest {
  double first = 0.0, second = 0.0;
  void take(double v) {
    if (v <= second) return;
    if (v > first)
      second = first, first = v;
    else
      second = v;
  }
  void merge(const TwoLargest& o) {
    take(o.first);
    take(o.second);
  }
};

}  // namespace silodem
