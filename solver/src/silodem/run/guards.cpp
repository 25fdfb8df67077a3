#include "silodem/run/guards.hpp"

#include "silodem/checkpoint/archive.hpp"

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "silodem/case/feasibility.hpp"
#include "silodem/case/initial_contacts.hpp"
#include "silodem/contact/pair_constants.hpp"
#include "silodem/core/parallel.hpp"
#include "silodem/core/partition.hpp"
#include "silodem/run/simulation.hpp"

namespace silodem {

namespace {

/// "(x, y, z)", or "(not finite)": messages go into summary.json, which holds no nan or inf.
std::string vec_text(const Vec3& v, const char* format) {
  if (!v.allFinite()) return "(not finite)";
  char b[96];
  std::snprintf(b, sizeof b, format, v.x(), v.y(), v.z());
  return b;
}

std::string where(const Particles& p, std::size_t i) {
  return "ball \"" + p.id[i] + "\" at " + vec_text(p.x[i], "(%.6g, %.6g, %.6g)") + " m, v = " +
         vec_text(p.v[i], "(%.4g, %.4g, %.4g)") + " m/s";
}

std::string when(long step, double t) {
  char b[64];
  std::snprintf(b, sizeof b, " at step %ld, t = %.6g s", step, t);
  return b;
}

/// Δt against the contact time of the pair (i, j) with the undamped ω0 = √(k/m_eff).
std::string cause(const Particles& p, std::size_t i, std::size_t j, double dt) {
  const double k = contact::series(p.k[i], p.k[j]);
  const double m_eff = p.fixed(j) ? p.m[i] : p.m[i] * p.m[j] / (p.m[i] + p.m[j]);
  const double tc = std::acos(-1.0) * std::sqrt(m_eff / k);
  char b[200];
  std::snprintf(b, sizeof b, "; likely cause: the time step %.3g s is %.3g of this pair's contact time %.3g s (stable and "
                "accurate needs about 1/25 or less), or an impact faster than the stiffness can stop", dt, dt / tc, tc);
  return b;
}

/// The ball sharing i's centre (closer than kSameCentreFraction of the smaller radius), if any:
/// the one cause of a non-finite contact force between finite positions. Pairs are stored under
/// the lower mobile index, so both i's own slots and those naming it are searched.
std::optional<std::size_t> same_centre_partner(const Particles& p, const NeighbourList& list, std::size_t i) {
  const auto close = [&](std::size_t j) {
    return (p.x[i] - p.x[j]).norm() < kSameCentreFraction * std::min(p.r[i], p.r[j]);
  };
  for (std::size_t s = list.begin(i); s < list.end(i); ++s)
    if (close(list.neighbour(s))) return list.neighbour(s);
  for (std::size_t k = list.reverse_begin(i); k < list.reverse_end(i); ++k) {
    const std::size_t owner = list.owner(list.reverse_slot(k));
    if (close(owner)) return owner;
  }
  return std::nullopt;
}

}  // namespace

RunGuards::RunGuards(const CaseConfig& cfg, const Particles& p) : cfg_(cfg), start_(std::chrono::steady_clock::now()) {
  lo_ = Vec3::Constant(INFINITY);
  hi_ = Vec3::Constant(-INFINITY);
  for (std::size_t i = 0; i < p.size(); ++i) {
    lo_ = lo_.cwiseMin(p.x[i]);
    hi_ = hi_.cwiseMax(p.x[i]);
  }
  if (cfg.drops) {
    const auto& d = *cfg.drops;
    if (d.positions.empty()) {  // the inlet rectangle at the release height
      lo_ = lo_.cwiseMin(Vec3(d.x_min, d.y_min, d.z0));
      hi_ = hi_.cwiseMax(Vec3(d.x_max, d.y_max, d.z0));
    }
    for (const auto& xy : d.positions) {
      lo_ = lo_.cwiseMin(Vec3(xy[0], xy[1], d.z0));
      hi_ = hi_.cwiseMax(Vec3(xy[0], xy[1], d.z0));
    }
  }
  lo_.array() -= cfg.guards.domain_margin;
  hi_.array() += cfg.guards.domain_margin;
  r_min_ = smallest_radius(cfg);
  const double v_max = cfg.guards.max_travel_ratio * r_min_ / cfg.dt;
  max_speed2_ = v_max * v_max;
}

void RunGuards::name_offender(const Particles& p, const NeighbourList& list, long step, double t) const {
  const GuardSpec& g = cfg_.guards;
  const BallRange own = owned_mobile(p.n_mobile);
  for (std::size_t i = own.begin; i < own.end; ++i) {
    // Which quantity went non-finite first: a position, then a force between finite positions
    // (two balls at one centre), then a velocity (the force or the state before it blew up).
    if (!p.x[i].allFinite())
      throw RunError(where(p, i) + " has a non-finite position" + when(step, t) +
                     ": the state blew up; likely cause: the time step is too long for its stiffest contact, or an "
                     "overlap too deep for the contact law (see the series' max_overlap_ratio before this step)");
    if (!p.f[i].allFinite()) {
      const auto j = same_centre_partner(p, list, i);
      throw RunError(where(p, i) + " has a non-finite contact force" + when(step, t) +
                     (j ? ": it has come to the same centre as ball \"" + p.id[*j] +
                              "\", where the contact normal is 0/0; likely cause: the two passed through each other "
                              "(too fast for their stiffness or for the time step)"
                        : ": likely cause: a force too large to represent, from an overlap or speed beyond the "
                          "contact law's range"));
    }
    if (!p.v[i].allFinite())
      throw RunError(where(p, i) + " has a non-finite velocity" + when(step, t) +
                     ": likely cause: the time step is too long for its stiffest contact");
    if ((p.x[i].array() < lo_.array()).any() || (p.x[i].array() > hi_.array()).any())
      throw RunError(where(p, i) + " has left the domain (the initial balls' bounding box widened by " +
                     std::to_string(g.domain_margin) + " m, guards.domain_margin)" + when(step, t) +
                     ": a blow-up flung it out, or a wall has a hole (an outlet without outflow?)");
    if (p.v[i].squaredNorm() > max_speed2_) {  // the scan's own test
      const double speed = p.v[i].norm();
      char b[400];
      std::snprintf(b, sizeof b,
                    " moves %.4g m per step at %.4g m/s (dt = %.4g s), more than guards.max_travel_ratio = %.4g of "
                    "the smallest radius %.4g m: between two steps it can pass through a ball without touching it; "
                    "a time step of at most %.4g s would resolve this speed",
                    speed * cfg_.dt, speed, cfg_.dt, g.max_travel_ratio, r_min_, g.max_travel_ratio * r_min_ / speed);
      throw RunError(where(p, i) + b + when(step, t) +
                     "; likely cause: an impact or a blow-up flung it, or a fall longer than the time step allows");
    }
  }
}

void RunGuards::check(const Particles& p, const NeighbourList& list, const ForceTotals& totals, const EnergyState& ledger,
                      long step, double t) const {
  const GuardSpec& g = cfg_.guards;
  // Every step: one branch-free scan (NaN fails every comparison, and v·0 is 0 only for finite v);
  // only if it finds something does the loop below look for the first offending ball to name.
  // A process of a partitioned run answers for its own balls (ghosts are others' to check).
  const BallRange own = owned_mobile(p.n_mobile);
  const long first = long(own.begin), nm = long(own.end);
  const double lx = lo_.x(), ly = lo_.y(), lz = lo_.z(), hx = hi_.x(), hy = hi_.y(), hz = hi_.z();
  const double v2_max = max_speed2_;
  int ok = 1;
#if defined(_OPENMP)
#pragma omp parallel for schedule(static) reduction(& : ok) num_threads(detail::g_threads) if (detail::g_threads > 1)
#endif
  for (long il = first; il < nm; ++il) {
    const Vec3& x = p.x[std::size_t(il)];
    const Vec3& v = p.v[std::size_t(il)];
    const Vec3& f = p.f[std::size_t(il)];
    // The forces on wall balls are sums of the same pair forces as these (each pair has a mobile
    // ball), so they are finite when these are.
    ok &= int(x.x() >= lx) & int(x.x() <= hx) & int(x.y() >= ly) & int(x.y() <= hy) & int(x.z() >= lz) &
          int(x.z() <= hz) & int(v.squaredNorm() <= v2_max) & int(f.x() * 0.0 == 0.0) & int(f.y() * 0.0 == 0.0) &
          int(f.z() * 0.0 == 0.0);
  }
  if (!ok) name_offender(p, list, step, t);
  // What the result files take from the step besides the balls: the ledger and the force totals.
  const std::pair<const char*, double> scalars[] = {
      {"kinetic energy", ledger.kinetic},       {"gravitational energy", ledger.gravitational},
      {"elastic energy", ledger.elastic},       {"dissipated energy", ledger.dissipated},
      {"cohesion energy removed", ledger.cohesion_removed}, {"ledger balance", ledger.balance},
      {"ledger scale", ledger.scale},           {"largest overlap ratio", totals.max_overlap_ratio},
      {"dashpot power", totals.p_dissipated}};
  for (const auto& [name, value] : scalars)
    if (!std::isfinite(value))
      throw RunError(std::string("the ") + name + " is not finite" + when(step, t) +
                     " while every ball's position, velocity and force is finite: likely cause: a sum beyond the "
                     "double range (speeds or overlaps far outside the contact law's range)");
  if (totals.max_overlap_ratio > g.max_overlap_ratio) {
    // Only now look for the pair: the force loop keeps just the largest ratio.
    for (std::size_t i = 0; i < p.n_mobile; ++i)
      for (std::size_t s = list.begin(i); s < list.end(i); ++s) {
        const std::size_t j = list.neighbour(s);
        const double delta = p.r[i] + p.r[j] - (p.x[i] - p.x[j]).norm();
        if (delta / std::min(p.r[i], p.r[j]) >= totals.max_overlap_ratio * (1.0 - 1e-12))
          throw RunError(where(p, i) + " overlaps \"" + p.id[j] + "\" by " + std::to_string(delta / std::min(p.r[i], p.r[j])) +
                         " of the smaller radius (guards.max_overlap_ratio " + std::to_string(g.max_overlap_ratio) + ")" +
                         when(step, t) + cause(p, i, j, cfg_.dt));
      }
    throw RunError("an overlap of " + std::to_string(totals.max_overlap_ratio) + " of the smaller radius" + when(step, t) +
                   " (guards.max_overlap_ratio " + std::to_string(g.max_overlap_ratio) + ")");
  }
  // Not in the first 100 steps, and only once it has lasted 100 steps: while the energy moved is
  // still tiny (a start, a wall's first touch of a grain at rest) the ratio is noise.
  steps_drifting_ = std::abs(ledger.relative_drift()) > g.max_energy_drift ? steps_drifting_ + 1 : 0;
  if (step - cfg_.start_step > 100 && steps_drifting_ > 100)
    throw RunError("the energy ledger no longer balances: |balance| / energy moved = " +
                   std::to_string(std::abs(ledger.relative_drift())) + " (guards.max_energy_drift " +
                   std::to_string(g.max_energy_drift) + ")" + when(step, t) +
                   ": energy is being created, the signature of an unstable time step");
  if (g.max_steps > 0 && step - cfg_.start_step >= g.max_steps)
    throw RunError("the step limit guards.max_steps = " + std::to_string(g.max_steps) + " was reached" + when(step, t) +
                   " before the run ended");
  if (g.max_wall_seconds > 0.0 && (step & 63) == 0 &&
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count() > g.max_wall_seconds)
    throw RunError("the wall-clock limit guards.max_wall_seconds = " + std::to_string(g.max_wall_seconds) +
                   " s was reached" + when(step, t) + " before the run ended");
}

void RunGuards::serialize(Archive& a) {
  double used = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  a & lo_ & hi_ & used;
  if (a.loading() && !(used >= 0.0 && used < 1e12)) throw CheckpointError("checkpoint payload is damaged (wall time)");
  if (a.loading())
    start_ = std::chrono::steady_clock::now() - std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                    std::chrono::duration<double>(used));
}

}  // namespace silodem
