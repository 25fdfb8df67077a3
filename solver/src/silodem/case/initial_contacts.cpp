#include "silodem/case/initial_contacts.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>

#include "silodem/case/case_error.hpp"
#include "silodem/case/json_reader.hpp"

namespace silodem {

namespace {

/// The balls of one octave of radius [2^L r_min, 2^(L+1) r_min) in a cell grid of edge at least
/// twice their largest radius: a ball no larger than those finds every ball of the octave it
/// touches in the 27 cells around its own.
class OctaveGrid {
 public:
  OctaveGrid(const std::vector<BallSpec>& balls, const std::vector<std::uint32_t>& members) {
    Vec3 lo = balls[members[0]].position, hi = lo;
    double r_top = 0.0;
    for (const auto i : members) {
      lo = lo.cwiseMin(balls[i].position);
      hi = hi.cwiseMax(balls[i].position);
      r_top = std::max(r_top, balls[i].radius);
    }
    lo_ = lo;
    edge_ = 2.0 * r_top;
    // At most a few cells per ball, as the neighbour list does: far-flung balls coarsen the grid
    // instead of making it huge.
    const double cap = std::max(64.0, 4.0 * double(members.size()));
    for (;;) {
      double cells = 1.0;
      for (int d = 0; d < 3; ++d) {
        const double q = std::floor((hi[d] - lo[d]) / edge_) + 1.0;
        dims_[d] = q > cap ? long(cap) + 1 : long(q);
        cells *= double(dims_[d]);
      }
      if (cells <= cap) break;
      edge_ *= 1.5;
    }
    start_.assign(std::size_t(dims_[0] * dims_[1] * dims_[2]) + 1, 0);
    std::vector<std::size_t> cell_of(members.size());
    for (std::size_t k = 0; k < members.size(); ++k) {
      const Vec3& x = balls[members[k]].position;
      cell_of[k] = std::size_t((clamped(x, 0) * dims_[1] + clamped(x, 1)) * dims_[2] + clamped(x, 2));
      ++start_[cell_of[k] + 1];
    }
    for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    members_.resize(members.size());
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t k = 0; k < members.size(); ++k) members_[fill[cell_of[k]]++] = members[k];
  }

  /// Calls visit(j) for every ball of the octave in the 27 cells around x.
  template <class Visit>
  void around(const Vec3& x, Visit&& visit) const {
    std::array<long, 3> from{}, to{};
    for (int d = 0; d < 3; ++d) {
      // Clamped before the conversion: x may lie far outside this octave's box.
      const double q = std::clamp(std::floor((x[d] - lo_[d]) / edge_), -2.0, double(dims_[d]) + 1.0);
      from[d] = std::max(0L, long(q) - 1);
      to[d] = std::min(dims_[d] - 1, long(q) + 1);
      if (from[d] > to[d]) return;
    }
    for (long a = from[0]; a <= to[0]; ++a)
      for (long b = from[1]; b <= to[1]; ++b) {
        const std::size_t row = std::size_t((a * dims_[1] + b) * dims_[2]);
        for (std::uint32_t s = start_[row + std::size_t(from[2])]; s < start_[row + std::size_t(to[2]) + 1]; ++s)
          visit(members_[s]);
      }
  }

 private:
  long clamped(const Vec3& x, int d) const { return std::min(dims_[d] - 1, long((x[d] - lo_[d]) / edge_)); }
  Vec3 lo_;
  double edge_ = 0.0;
  std::array<long, 3> dims_{};
  std::vector<std::uint32_t> start_, members_;
};

std::string ball_named(const CaseConfig& cfg, std::size_t i,
                       const std::function<std::string(std::size_t)>& path_of) {
  return "ball \"" + cfg.balls[i].id + "\" (" + path_of(i) + ")";
}

}  // namespace

void check_initial_contacts(const CaseConfig& cfg, const std::function<std::string(std::size_t)>& path_of) {
  const auto& balls = cfg.balls;
  if (balls.empty()) return;
  std::set<std::string> released;
  for (const auto& e : cfg.events)
    if (e.type == "open_outlet" && e.release_mobile) released.insert(e.wall + "_");
  const auto is_released = [&](const BallSpec& b) {
    if (!b.fixed || released.empty()) return false;
    const auto cut = b.id.rfind('_');
    return cut != std::string::npos && released.count(b.id.substr(0, cut + 1)) > 0;
  };
  // Balls that meet others: mobile now, or mobile once their wall is released.
  std::vector<char> active(balls.size());
  double r_min = INFINITY;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    active[i] = char(!balls[i].fixed || is_released(balls[i]));
    r_min = std::min(r_min, balls[i].radius);
  }
  // Octaves by floor(log2(r / r_min)): monotone in r, so a ball of a higher octave is never smaller.
  std::vector<int> octave(balls.size());
  std::map<int, std::vector<std::uint32_t>> members;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    octave[i] = int(std::floor(std::log2(balls[i].radius / r_min)));
    members[octave[i]].push_back(std::uint32_t(i));
  }
  std::vector<std::pair<int, OctaveGrid>> grids;
  for (const auto& [o, m] : members) grids.emplace_back(o, OctaveGrid(balls, m));

  const double ratio = cfg.guards.max_overlap_ratio;
  const auto test = [&](std::size_t i, std::size_t j) {
    const BallSpec &a = balls[std::min(i, j)], &b = balls[std::max(i, j)];
    const double d = (a.position - b.position).norm(), r_small = std::min(a.radius, b.radius);
    const std::string first = ball_named(cfg, std::min(i, j), path_of);
    if (d < kSameCentreFraction * r_small)
      throw CaseError(path_of(std::max(i, j)),
                      "ball \"" + b.id + "\" and " + first + " are at the same centre (" + format_number(d) +
                          " m apart, less than " + format_number(kSameCentreFraction) + " of the smaller radius " +
                          format_number(r_small) + " m): the contact normal between them is undefined; is a ball "
                          "written twice?");
    const double overlap = (a.radius + b.radius - d) / r_small;
    if ((!a.fixed || !b.fixed) && overlap > ratio)
      throw CaseError(path_of(std::max(i, j)),
                      "ball \"" + b.id + "\" overlaps " + first + " by " + format_number(overlap) +
                          " of the smaller radius at the start, more than guards.max_overlap_ratio = " +
                          format_number(ratio) + ": the overlap guard would stop the run at its first step; "
                          "move the balls apart");
  };
  // Each pair with an active ball once: from its smaller ball (the lower octave) into the larger
  // one's octave; within one octave from the active ball, and from the lower index if both are.
  for (std::size_t i = 0; i < balls.size(); ++i)
    for (const auto& entry : grids) {
      const int o = entry.first;  // a plain variable: C++17 lambdas cannot capture a structured binding
      const auto& grid = entry.second;
      if (o < octave[i] || (o == octave[i] && !active[i])) continue;
      grid.around(balls[i].position, [&](std::uint32_t j) {
        if (j == i || (!active[i] && !active[j])) return;
        if (o == octave[i] && active[j] && j < i) return;  // found from j
        const double reach = balls[i].radius + balls[j].radius;
        if ((balls[i].position - balls[j].position).squaredNorm() < reach * reach) test(i, j);
      });
    }
}

}  // namespace silodem
