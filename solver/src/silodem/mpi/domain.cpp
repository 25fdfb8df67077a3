#include "silodem/mpi/domain.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "silodem/core/parallel.hpp"
#include "silodem/core/run_error.hpp"
#include "silodem/neighbour/spatial_order.hpp"
#include "silodem/neighbour/two_largest.hpp"

namespace silodem::mpi {

namespace {

struct Writer {
  std::vector<char> bytes;
  template <class T>
  void put(const T& v) {
    const std::size_t at = bytes.size();
    bytes.resize(at + sizeof(T));
    std::memcpy(&bytes[at], &v, sizeof(T));
  }
  void put_string(const std::string& s) {
    put(std::uint32_t(s.size()));
    bytes.insert(bytes.end(), s.begin(), s.end());
  }
};

struct Reader {
  const char* at;
  const char* end;
  template <class T>
  T get() {
    if (std::size_t(end - at) < sizeof(T)) throw std::logic_error("a ball record from another process is cut short");
    T v;
    std::memcpy(static_cast<void*>(&v), at, sizeof(T));  // plain bytes: doubles and integers only
    at += sizeof(T);
    return v;
  }
  std::string get_string() {
    const std::uint32_t n = get<std::uint32_t>();
    if (std::size_t(end - at) < n) throw std::logic_error("a ball id from another process is cut short");
    std::string s(at, n);
    at += n;
    return s;
  }
};

void pack(Writer& w, const Domain::Record& r, bool rotating) {
  const Particles::Ball& b = r.ball;
  w.put(b.x), w.put(b.v), w.put(b.r), w.put(b.m), w.put(b.k), w.put(b.c), w.put(b.material), w.put(b.tag);
  w.put_string(b.id);
  w.put(r.a);
  if (rotating) w.put(b.w), w.put(r.alpha);
}

Domain::Record unpack(Reader& in, bool rotating) {
  Domain::Record r;
  Particles::Ball& b = r.ball;
  b.x = in.get<Vec3>(), b.v = in.get<Vec3>(), b.r = in.get<double>(), b.m = in.get<double>();
  b.k = in.get<double>(), b.c = in.get<double>(), b.material = in.get<std::int32_t>(), b.tag = in.get<std::int64_t>();
  b.id = in.get_string();
  r.a = in.get<Vec3>();
  if (rotating) b.w = in.get<Vec3>(), r.alpha = in.get<Vec3>();
  return r;
}


}  // namespace

std::vector<Domain::Record> Domain::gather_owned(const Particles& p, const Integrator* integrator) const {
  const bool carried = integrator && !integrator->acceleration().empty();
  Writer w;
  for (std::size_t i = part_.own_begin; i < part_.own_end; ++i) {
    Record r{p.ball(i)};
    if (carried) {
      r.a = integrator->acceleration()[i];
      if (p.rotating) r.alpha = integrator->angular_acceleration()[i];
    }
    pack(w, r, p.rotating);
  }
  std::vector<Record> all;
  for (const auto& piece : part_.gather_all(w.bytes.data(), w.bytes.size())) {
    Reader in{piece.data(), piece.data() + piece.size()};
    while (in.at != in.end) all.push_back(unpack(in, p.rotating));
  }
  return all;
}

void Domain::distribute(Particles& p, Integrator& integrator) {
  std::vector<Record> all;
  all.reserve(p.n_mobile);
  for (std::size_t i = 0; i < p.n_mobile; ++i) all.push_back({p.ball(i)});
  share(std::move(all), p, integrator, false);
}

void Domain::redistribute(Particles& p, Integrator& integrator, ForceField& field, bool renumber) {
  // The history of every pair whose owner is owned here: the authoritative copy (a ghost's
  // process computes the same state, but only the owner's is sent).
  const std::vector<char> mine = field.export_history(part_.own_begin, part_.own_end);
  std::vector<char> history;
  for (const auto& piece : part_.gather_all(mine.data(), mine.size())) history.insert(history.end(), piece.begin(), piece.end());
  std::vector<Record> all = gather_owned(p, &integrator);
  if (renumber && all.size() >= 2) {
    // What the one-process run does (run/simulation.cpp, renumber_mobile), on the same balls.
    Particles positions;
    double r_min = INFINITY;
    for (const Record& r : all) positions.x.push_back(r.ball.x), r_min = std::min(r_min, r.ball.r);
    positions.n_mobile = all.size();
    const std::vector<std::uint32_t> order = sweep_order(positions, 2.0 * r_min);
    if (!std::is_sorted(order.begin(), order.end())) permute_front(all, order);
  }
  share(std::move(all), p, integrator, !integrator.acceleration().empty());
  field.adopt_history(history);
  ++redistributions_;
}

void Domain::reselect_ghosts(Particles& p, Integrator& integrator) {
  const std::size_t ranks = std::size_t(part_.ranks()), me = std::size_t(part_.rank());
  const std::size_t b = part_.own_begin, e = part_.own_end, first = range_begin_[me];
  // Every process's widened box of its own balls (an empty share: a box nothing is inside).
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (std::size_t i = b; i < e; ++i) lo = lo.cwiseMin(p.x[i]), hi = hi.cwiseMax(p.x[i]);
  lo.array() -= pair_reach_ + margin_;
  hi.array() += pair_reach_ + margin_;
  const std::vector<double> boxes = part_.gather_values(std::vector<double>{lo.x(), lo.y(), lo.z(), hi.x(), hi.y(), hi.z()});
  // Each owner sends the balls inside another's box, in its order: the receiver's ghosts, and the
  // refresh plan on both sides, without a round of requests.
  std::vector<std::vector<char>> to(ranks);
  send_.assign(ranks, {});
  std::vector<std::uint32_t> kept;  // the owned balls' old local indices, in order
  for (std::size_t q = 0; q < ranks; ++q) {
    if (q == me) continue;
    const Vec3 qlo(boxes[6 * q], boxes[6 * q + 1], boxes[6 * q + 2]), qhi(boxes[6 * q + 3], boxes[6 * q + 4], boxes[6 * q + 5]);
    Writer w;
    for (std::size_t i = b; i < e; ++i)
      if ((p.x[i].array() >= qlo.array()).all() && (p.x[i].array() <= qhi.array()).all()) {
        w.put(std::uint64_t(first + (i - b)));
        pack(w, {p.ball(i)}, p.rotating);
        send_[q].push_back(std::uint32_t(i - b));  // made local below, once the lower ghosts are counted
      }
    to[q] = std::move(w.bytes);
  }
  const auto from = part_.exchange(to);
  std::vector<std::uint64_t> global;
  std::vector<Record> ghosts;
  std::vector<std::size_t> per_rank(ranks, 0);
  for (std::size_t q = 0; q < ranks; ++q) {  // ranks in order, each in its order: ascending global index
    Reader in{from[q].data(), from[q].data() + from[q].size()};
    for (; in.at != in.end; ++per_rank[q]) {
      global.push_back(in.get<std::uint64_t>());
      ghosts.push_back(unpack(in, p.rotating));
    }
  }
  ++redistributions_;
  const std::size_t n_lower = std::size_t(std::lower_bound(global.begin(), global.end(), std::uint64_t(first)) - global.begin());
  for (auto& list : send_)
    for (auto& i : list) i += std::uint32_t(n_lower);
  if (global == ghost_global_) {  // the same ghosts (a bed at rest): nothing to rebuild
    x_at_share_.assign(p.x.begin() + std::ptrdiff_t(b), p.x.begin() + std::ptrdiff_t(e));
    return;
  }
  Particles q = p.empty_like();
  q.reserve(ghosts.size() + (e - b) + (p.size() - p.n_mobile));
  for (std::size_t k = 0; k < n_lower; ++k) q.add(ghosts[k].ball, false);
  for (std::size_t i = b; i < e; ++i) q.add(p.ball(i), false);
  for (std::size_t k = n_lower; k < ghosts.size(); ++k) q.add(ghosts[k].ball, false);
  for (std::size_t i = p.n_mobile; i < p.size(); ++i) q.add(p.ball(i), true);
  q.topology = p.topology + 1;
  // ü and ω̇ of the own balls move with them; a ghost's are never read.
  for (std::vector<Vec3>* carried : {&integrator.carried_acceleration(), &integrator.carried_angular_acceleration()}) {
    if (carried->empty()) continue;
    std::vector<Vec3> moved(q.n_mobile, Vec3::Zero());
    std::copy(carried->begin() + std::ptrdiff_t(b), carried->begin() + std::ptrdiff_t(e), moved.begin() + std::ptrdiff_t(n_lower));
    carried->swap(moved);
  }
  recv_.assign(ranks, {});
  for (std::size_t qr = 0, k = 0; qr < ranks; ++qr)
    for (std::size_t c = 0; c < per_rank[qr]; ++c, ++k) recv_[qr].push_back(std::uint32_t(k < n_lower ? k : (e - b) + k));
  ghost_global_ = std::move(global);
  part_.own_begin = n_lower;
  part_.own_end = n_lower + (e - b);
  x_at_share_.assign(q.x.begin() + std::ptrdiff_t(n_lower), q.x.begin() + std::ptrdiff_t(n_lower + (e - b)));
  p = std::move(q);
}

void Domain::share(std::vector<Record> all, Particles& p, Integrator& integrator, bool carried) {
  const std::size_t n = all.size(), ranks = std::size_t(part_.ranks()), me = std::size_t(part_.rank());
  global_mobile_ = n;
  // Equal shares cut at the chunk edge nearest to them: every sum over balls starts its chunks
  // where one process would. (At 5,000 balls on 2 processes a cut rounded down gave 2,048 and
  // 2,952 balls; at 10^5 the nearest edge is within 0.3 % of an equal share.)
  range_begin_.assign(ranks + 1, n);
  for (std::size_t q = 0; q < ranks; ++q)
    range_begin_[q] = std::min(n, (q * n / ranks + kSumChunk / 2) / kSumChunk * kSumChunk);
  const std::size_t b = range_begin_[me], e = range_begin_[me + 1];

  // Ghosts: every other ball inside the box of the owned ones widened by the pair reach and the
  // margin. A box, not the exact distance: more ghosts than needed at worst, never fewer.
  std::vector<std::uint64_t> lower, upper;
  if (b < e) {
    Vec3 lo = all[b].ball.x, hi = lo;
    for (std::size_t i = b; i < e; ++i) lo = lo.cwiseMin(all[i].ball.x), hi = hi.cwiseMax(all[i].ball.x);
    lo.array() -= pair_reach_ + margin_;
    hi.array() += pair_reach_ + margin_;
    for (std::size_t g = 0; g < n; ++g) {
      if (g == b) g = e;
      if (g >= n) break;
      const Vec3& x = all[g].ball.x;
      if ((x.array() >= lo.array()).all() && (x.array() <= hi.array()).all()) (g < b ? lower : upper).push_back(g);
    }
  }

  Particles q = p.empty_like();
  q.reserve(lower.size() + (e - b) + upper.size() + (p.size() - p.n_mobile));
  for (const std::uint64_t g : lower) q.add(all[g].ball, false);
  for (std::size_t g = b; g < e; ++g) q.add(all[g].ball, false);
  for (const std::uint64_t g : upper) q.add(all[g].ball, false);
  for (std::size_t i = p.n_mobile; i < p.size(); ++i) q.add(p.ball(i), true);
  q.topology = p.topology + 1;  // every index changed: the list rebuilds, the history follows tags

  ghost_global_ = lower;
  ghost_global_.insert(ghost_global_.end(), upper.begin(), upper.end());
  if (carried) {
    std::vector<Vec3>& a = integrator.carried_acceleration();
    std::vector<Vec3>& alpha = integrator.carried_angular_acceleration();
    a.assign(q.n_mobile, Vec3::Zero());
    if (p.rotating) alpha.assign(q.n_mobile, Vec3::Zero());
    std::size_t k = 0;
    const auto take = [&](std::size_t g) {
      a[k] = all[g].a;
      if (p.rotating) alpha[k] = all[g].alpha;
      ++k;
    };
    for (const std::uint64_t g : lower) take(g);
    for (std::size_t g = b; g < e; ++g) take(g);
    for (const std::uint64_t g : upper) take(g);
  }

  // The refresh plan: each process asks the owners of its ghosts for them, in its local order.
  const std::size_t n_lower = lower.size(), n_owned = e - b;
  std::vector<std::vector<char>> asks(ranks);
  recv_.assign(ranks, {});
  for (std::size_t k = 0; k < ghost_global_.size(); ++k) {
    const std::uint64_t g = ghost_global_[k];
    const std::size_t owner = std::size_t(std::upper_bound(range_begin_.begin(), range_begin_.end() - 1, g) - range_begin_.begin()) - 1;
    Writer w{std::move(asks[owner])};
    w.put(g);
    asks[owner] = std::move(w.bytes);
    recv_[owner].push_back(std::uint32_t(k < n_lower ? k : n_owned + k));
  }
  const auto asked = part_.exchange(asks);
  send_.assign(ranks, {});
  for (std::size_t r = 0; r < ranks; ++r) {
    Reader in{asked[r].data(), asked[r].data() + asked[r].size()};
    while (in.at != in.end) send_[r].push_back(std::uint32_t(in.get<std::uint64_t>() - b + n_lower));
  }
  part_.own_begin = n_lower;
  part_.own_end = n_lower + n_owned;
  x_at_share_.assign(q.x.begin() + std::ptrdiff_t(n_lower), q.x.begin() + std::ptrdiff_t(n_lower + n_owned));
  p = std::move(q);
}

void Domain::refresh_ghosts(Particles& p) const {
  const std::size_t ranks = std::size_t(part_.ranks());
  std::vector<std::vector<char>> out(ranks);
  for (std::size_t r = 0; r < ranks; ++r) {
    Writer w;
    for (const std::uint32_t i : send_[r]) {
      w.put(p.x[i]), w.put(p.v[i]);
      if (p.rotating) w.put(p.w[i]);
    }
    out[r] = std::move(w.bytes);
  }
  std::vector<std::size_t> sizes(ranks);
  const std::size_t per_ball = (p.rotating ? 3 : 2) * sizeof(Vec3);
  for (std::size_t r = 0; r < ranks; ++r) sizes[r] = recv_[r].size() * per_ball;
  const auto in = part_.exchange(out, &sizes);
  for (std::size_t r = 0; r < ranks; ++r) {
    Reader rd{in[r].data(), in[r].data() + in[r].size()};
    for (const std::uint32_t i : recv_[r]) {
      p.x[i] = rd.get<Vec3>(), p.v[i] = rd.get<Vec3>();
      if (p.rotating) p.w[i] = rd.get<Vec3>();
    }
  }
}

bool Domain::redistribution_due(const Particles& p) const {
  TwoLargest moved;
  for (std::size_t i = part_.own_begin; i < part_.own_end; ++i)
    moved.take((p.x[i] - x_at_share_[i - part_.own_begin]).squaredNorm());
  TwoLargest all;
  for (const double d2 : part_.gather_values(std::vector<double>{moved.first, moved.second})) all.take(d2);
  // Two balls that were margin_ farther apart than the list reaches cannot have come within it
  // while their displacements add up to less than the margin.
  const double closed = std::sqrt(all.first) + std::sqrt(all.second);
  if (closed >= margin_)
    throw RunError("balls moved " + std::to_string(closed) + " m toward each other in one step, beyond the ghost margin " +
                   std::to_string(margin_) + " m of the MPI decomposition: a pair across two processes may have been "
                   "missed (the time step is too long for the speeds, or the state blew up)");
  return closed >= 0.5 * margin_;
}

}  // namespace silodem::mpi
