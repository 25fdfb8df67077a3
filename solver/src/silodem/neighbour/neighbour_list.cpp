#include "silodem/neighbour/neighbour_list.hpp"

#include "silodem/checkpoint/archive.hpp"
#include "silodem/core/run_error.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "silodem/core/parallel.hpp"
#include "silodem/neighbour/spatial_order.hpp"
#include "silodem/neighbour/two_largest.hpp"

namespace silodem {


#if defined(_OPENMP)
#pragma omp declare reduction(two_largest : TwoLargest : omp_out.merge(omp_in)) initializer(omp_priv = TwoLargest{})
#endif

// A pair left out of the list was at least r_i + r_j + reach + skin apart at the build; it can
// have closed by at most d_i + d_j, its balls' displacements since, and that sum is at most the
// two largest displacements' (static walls do not move; a moving wall's balls count like mobile
// ones). So the list holds every interacting pair while d_1 + d_2 < skin. LAMMPS's test,
// d_1 > skin/2, is the same bound with d_2 taken as large as d_1: it rebuilds earlier whenever
// the fastest ball outruns the next one.
bool NeighbourList::update(const Particles& p) {
  // Moving walls (a move_wall event) are tracked like mobile balls; static ones cost nothing.
  const std::size_t tracked = p.moving_walls ? p.size() : p.n_mobile;
  bool stale = p.topology != topology_at_build_ || x_at_build_.size() != tracked;
  if (!stale) {
    const long n = long(tracked);
    TwoLargest moved;
#if defined(_OPENMP)
#pragma omp parallel for schedule(static) reduction(two_largest : moved) num_threads(detail::g_threads) if (detail::g_threads > 1)
#endif
    for (long i = 0; i < n; ++i) moved.take((p.x[std::size_t(i)] - x_at_build_[std::size_t(i)]).squaredNorm());
    stale = std::sqrt(moved.first) + std::sqrt(moved.second) >= skin_;
  }
  if (stale) build(p);
  return stale;
}

void NeighbourList::build(const Particles& p) {
  ++builds_;
  topology_at_build_ = p.topology;
  x_at_build_.assign(p.x.begin(), p.x.begin() + std::ptrdiff_t(p.moving_walls ? p.size() : p.n_mobile));
  const std::size_t n = p.size();
  offsets_.assign(p.n_mobile + 1, 0);
  list_.clear();
  owner_.clear();
  reverse_offsets_.assign(n + 1, 0);
  reverse_slots_.clear();
  front_ = 0;
  if (p.n_mobile == 0) return;

  // Grid over the mobile balls' bounding box widened by the largest pair reach (the cell edge):
  // every listed pair has a mobile ball, so a wall ball beyond that box can be no one's neighbour
  // and is left out — walls far from the grains (a silo's empty upper mantle, a slab elsewhere)
  // cost neither cells nor binning.
  Vec3 lo = p.x[0], hi = p.x[0];
  double r_max = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    // A state that blew up within a step reaches the search before the run guards see it.
    if (!p.x[i].allFinite())
      throw RunError("ball " + p.id[i] + " has a non-finite position at the neighbour search: the state blew up "
                     "within one step (time step too long for the stiffest contact?)");
    if (i < p.n_mobile) lo = lo.cwiseMin(p.x[i]), hi = hi.cwiseMax(p.x[i]);
    r_max = std::max(r_max, p.r[i]);
  }
  double edge = 2.0 * r_max + reach_ + skin_;
  lo.array() -= edge;
  hi.array() += edge;
  const auto outside = [&](const Vec3& x) { return (x.array() < lo.array()).any() || (x.array() > hi.array()).any(); };
  // A few far-flung balls must not make the grid huge: cap the cell count at a few per ball.
  const double cap = std::max<double>(64.0, 4.0 * double(n));
  std::array<long, 3> dims{};
  for (;;) {
    double cells = 1.0;
    for (int d = 0; d < 3; ++d) {
      const double q = std::floor((hi[d] - lo[d]) / edge);  // finite, but may exceed a long
      dims[d] = q >= cap ? long(cap) + 1 : std::max(1L, long(q) + 1);
      cells *= double(dims[d]);
    }
    if (cells <= cap) break;
    edge *= 1.5;
  }
  const auto cell_of = [&](const Vec3& x, int d) {
    return std::min(dims[d] - 1, long((x[d] - lo[d]) / edge));
  };
  // Cells are numbered along the axes in the order the balls are (sweep_axes: slabs along the
  // longest extent, then the middle, then the shortest), so the search, walking the balls in
  // index order, walks the cells in memory order too. Numbered along fixed axes, a wide flat bed
  // (slabs along x, cells z-major) sent every ball's cell lookups a whole layer of cells apart.
  // The box is the grains' widened on every side alike, so its extents order as theirs do.
  const std::array<int, 3> ax = sweep_axes(hi - lo);  // slowest, middle, fastest-varying
  const std::size_t n_cells = std::size_t(dims[0] * dims[1] * dims[2]);
  cell_start_.assign(n_cells + 1, 0);
  ball_cell_.resize(n);
  constexpr std::uint32_t kNoCell = ~std::uint32_t(0);
  for (std::size_t i = 0; i < n; ++i) {
    if (i >= p.n_mobile && outside(p.x[i])) {
      ball_cell_[i] = kNoCell;
      continue;
    }
    const long c = (cell_of(p.x[i], ax[0]) * dims[ax[1]] + cell_of(p.x[i], ax[1])) * dims[ax[2]] + cell_of(p.x[i], ax[2]);
    ball_cell_[i] = std::uint32_t(c);
    ++cell_start_[std::size_t(c) + 1];
  }
  for (std::size_t c = 0; c < n_cells; ++c) cell_start_[c + 1] += cell_start_[c];
  cell_balls_.resize(cell_start_.back());
  cell_fill_.assign(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t i = 0; i < n; ++i)
    if (ball_cell_[i] != kNoCell) cell_balls_[cell_fill_[ball_cell_[i]]++] = std::uint32_t(i);

  // The candidate search runs per chunk of balls into the chunk's own buffer; the buffers are
  // joined in chunk order, so the list is the same for any thread count.
  const std::size_t chunks = sum_chunks(p.n_mobile);
  if (chunk_lists_.size() < chunks) chunk_lists_.resize(chunks);
  const long nc = long(chunks);
  SILODEM_PARALLEL_FOR_DYNAMIC
  for (long cl = 0; cl < nc; ++cl) {
    // Filled as a local (swapped in and out): neighbouring chunks' vector headers share cache
    // lines, and a push_back into them from two threads would bounce those lines.
    std::vector<std::uint32_t> out;
    out.swap(chunk_lists_[std::size_t(cl)]);
    out.clear();
    const std::size_t i_end = std::min(p.n_mobile, (std::size_t(cl) + 1) * kSumChunk);
    for (std::size_t i = std::size_t(cl) * kSumChunk; i < i_end; ++i) {
      const Vec3 xi = p.x[i];
      const double ri = p.r[i] + reach_ + skin_;
      const std::size_t first = out.size();
      const long c0 = cell_of(xi, ax[0]), c1 = cell_of(xi, ax[1]), c2 = cell_of(xi, ax[2]);
      const long d0 = dims[ax[0]], d1 = dims[ax[1]], d2 = dims[ax[2]];
      for (long u = std::max(0L, c0 - 1); u <= std::min(d0 - 1, c0 + 1); ++u)
        for (long w = std::max(0L, c1 - 1); w <= std::min(d1 - 1, c1 + 1); ++w) {
          // The three cells along the fastest axis are consecutive: one run of cell_balls_.
          const std::size_t row = std::size_t((u * d1 + w) * d2);
          const std::uint32_t s_begin = cell_start_[row + std::size_t(std::max(0L, c2 - 1))];
          const std::uint32_t s_end = cell_start_[row + std::size_t(std::min(d2 - 1, c2 + 1)) + 1];
          // Written without a branch on the data (about a third of the candidates pass, in no
          // learnable order): room for every candidate, then the count moves past the kept ones.
          std::size_t kept = out.size();
          out.resize(kept + (s_end - s_begin));
          for (std::uint32_t s = s_begin; s < s_end; ++s) {
            const std::uint32_t j = cell_balls_[s];
            const double cut = ri + p.r[j];
            out[kept] = j;
            // Each mobile–mobile pair once (under the lower index); mobile–wall under the mobile ball.
            kept += std::size_t(j > i) & std::size_t((xi - p.x[j]).squaredNorm() < cut * cut);
          }
          out.resize(kept);
        }
      // A ball's partners in index order, not in the order of the cells of this build: its force
      // sum then depends only on which pairs interact, so a list built at another step, or by
      // another process over its own share of the balls (mpi/domain.hpp), gives the same bits.
      std::sort(out.begin() + std::ptrdiff_t(first), out.end());
      offsets_[i + 1] = out.size();  // within the chunk; made global below
    }
    chunk_lists_[std::size_t(cl)].swap(out);
  }
  std::size_t total = 0;
  for (std::size_t cl = 0; cl < chunks; ++cl) total += chunk_lists_[cl].size();
  list_.resize(total);
  std::size_t at = 0;
  for (std::size_t cl = 0; cl < chunks; ++cl) {
    const std::size_t i_end = std::min(p.n_mobile, (cl + 1) * kSumChunk);
    for (std::size_t i = cl * kSumChunk; i < i_end; ++i) offsets_[i + 1] += at;
    std::copy(chunk_lists_[cl].begin(), chunk_lists_[cl].end(), list_.begin() + std::ptrdiff_t(at));
    at += chunk_lists_[cl].size();
  }
  fill_owners();
  // Reverse index by counting sort: slots in increasing order under each neighbour.
  for (const std::uint32_t j : list_) ++reverse_offsets_[j + 1];
  for (std::size_t j = 0; j < n; ++j) reverse_offsets_[j + 1] += reverse_offsets_[j];
  reverse_slots_.resize(list_.size());
  reverse_fill_.assign(reverse_offsets_.begin(), reverse_offsets_.end() - 1);
  for (std::size_t s = 0; s < list_.size(); ++s) reverse_slots_[reverse_fill_[list_[s]]++] = std::uint32_t(s);
  measure_front();
}

void NeighbourList::serialize(Archive& a, const Particles& p) {
  a & offsets_ & list_ & reverse_offsets_ & reverse_slots_ & x_at_build_ & topology_at_build_ & builds_;
  if (!a.loading()) return;
  const auto bad = [](const char* what) { throw CheckpointError(std::string("checkpoint payload is damaged (neighbour list: ") + what + ")"); };
  if (topology_at_build_ != p.topology) return;  // stale for this ball set: update() rebuilds it
  if (offsets_.size() != p.n_mobile + 1 || reverse_offsets_.size() != p.size() + 1) bad("sizes");
  if (offsets_.front() != 0 || offsets_.back() != list_.size() || reverse_offsets_.front() != 0 ||
      reverse_offsets_.back() != reverse_slots_.size() || reverse_slots_.size() != list_.size())
    bad("offsets");
  for (std::size_t i = 0; i + 1 < offsets_.size(); ++i)
    if (offsets_[i] > offsets_[i + 1]) bad("offsets not increasing");
  for (std::size_t i = 0; i + 1 < reverse_offsets_.size(); ++i)
    if (reverse_offsets_[i] > reverse_offsets_[i + 1]) bad("reverse offsets not increasing");
  for (const auto j : list_)
    if (j >= p.size()) bad("a neighbour beyond the balls");
  for (const auto s : reverse_slots_)
    if (s >= list_.size()) bad("a reverse slot beyond the list");
  fill_owners();
  measure_front();
}

void NeighbourList::fill_owners() {
  owner_.resize(list_.size());
  const std::size_t n_mobile = offsets_.empty() ? 0 : offsets_.size() - 1;
  for (std::size_t i = 0; i < n_mobile; ++i)
    std::fill(owner_.begin() + std::ptrdiff_t(offsets_[i]), owner_.begin() + std::ptrdiff_t(offsets_[i + 1]),
              std::uint32_t(i));
}

// A mobile j's pairs are stored under lower indices, and its reverse slots run in increasing
// order, so its first reverse slot belongs to its farthest owner: one look per mobile ball rather
// than a pass over every slot.
void NeighbourList::measure_front() {
  front_ = 0;
  const std::size_t n_mobile = offsets_.empty() ? 0 : offsets_.size() - 1;
  for (std::size_t j = 0; j < n_mobile; ++j)
    if (reverse_offsets_[j] != reverse_offsets_[j + 1])
      front_ = std::max(front_, j - std::size_t(owner_[reverse_slots_[reverse_offsets_[j]]]));
}

}  // namespace silodem
