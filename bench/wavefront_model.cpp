// A model of temporal blocking for the velocity-Verlet step (reports/perf_experiments.md, twelfth
// session): does sweeping several steps through the balls at once, each step a few sweep fronts
// behind the one before, take away the growth of the cost per ball-step from 5,000 to 10^6 balls?
// It runs the solver's own data (the case's scene, renumbered as the solver does, its neighbour
// list) through a copy of the one-thread force loop (frictionless Kelvin–Voigt, clamped, the
// half-step dashpot of the scaling beds; no onset correction, no cohesion) and the integrator's
// two passes; a case with another law or scheme is refused. Not the solver: no ledger, guards,
// probes or output, and the wavefront checks the list only at the start of each sweep (a redesign
// would have to check it every step). Experimental only; nothing here is used by the solver.
//
//   tools/build.sh    (builds build/bench/bench_wavefront_model)
//   OMP_NUM_THREADS=1 taskset -c 0 build/bench/bench_wavefront_model CASE.json STEPS ROUNDS K...
//   OMP_NUM_THREADS=1 build/bench/bench_wavefront_model --check CASE.json STEPS K
//
// K = 0 runs the plain loop (three passes per step: drift, forces, kick), K >= 1 the wavefront with
// K steps per sweep; the variants run in interleaved rounds from the same start, and the minimum
// of each is printed last. --check runs the wavefront and the plain loop with the list checked at
// the same steps and compares every position, velocity and wall force bit for bit; it also runs
// the plain loop against the solver's own ForceField and VelocityVerlet, which it must equal bit
// for bit (the copy of the loop here is the solver's, hints aside).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "silodem/case/case_loader.hpp"
#include "silodem/contact/contact_law.hpp"
#include "silodem/contact/pair_constants.hpp"
#include "silodem/core/parallel.hpp"
#include "silodem/forces/force_field.hpp"
#include "silodem/integrate/integrator.hpp"
#include "silodem/neighbour/neighbour_list.hpp"
#include "silodem/neighbour/spatial_order.hpp"
#include "silodem/scene/scene_builder.hpp"

using namespace silodem;

namespace {

constexpr std::size_t kBlock = 256;  // the solver's force chunk

struct Totals {
  double elastic = 0.0, dissipated = 0.0;
  std::size_t contacts = 0;
};

class Stepper {
 public:
  Stepper(Particles& p, NeighbourList& list, double dt, Vec3 g) : p_(p), list_(list), dt_(dt), g_(g) {
    nm_ = p.n_mobile;
    nb_ = (nm_ + kBlock - 1) / kBlock;
    a_.assign(nm_, Vec3::Zero());
    vh_.assign(nm_, Vec3::Zero());
  }

  /// The plain loop, as the solver runs it: drift all, forces of all, kick all. The list is
  /// checked every `check_every` steps: after the drift, where the solver checks it (`AfterDrift`),
  /// or before it, where the wavefront can (at the start of a sweep, before any ball has moved).
  enum class Check { AfterDrift, BeforeDrift };
  void plain_steps(long steps, long check_every, Check where, bool prefetch) {
    for (long s = 0; s < steps; ++s) {
      const bool check = s % check_every == 0;
      if (check && where == Check::BeforeDrift) timed_update();
      for (std::size_t i = 0; i < nm_; ++i) drift(i);
      if (check && where == Check::AfterDrift) timed_update();
      for (std::size_t j = 0; j < p_.size(); ++j) p_.f[j] = Vec3::Zero();
      Totals t;
      Vec3* wall_f = p_.f.data();
      for (std::size_t b = 0; b < nb_; ++b)
        prefetch ? forces<true>(b, wall_f + nm_, 1, t) : forces<false>(b, wall_f + nm_, 1, t);
      for (std::size_t i = 0; i < nm_; ++i) kick(i);
      last_ = t;
    }
  }

  /// K steps per sweep. Step k of a sweep drifts block b once step k-1 has kicked it, and computes
  /// the forces of block b (then kicks it) once it has drifted every block b's pairs reach.
  /// The mobile balls need one force array: pairs live under the lower index, so a ball's sum is
  /// complete when its own block is done, and the next step zeroes it only when it drifts the
  /// ball, after that kick. A wall receives from every step in flight, so it keeps K sums.
  void wavefront_steps(long steps, long K, bool prefetch) {
    // Each wall's K step sums side by side: a wall's line serves every step in flight.
    wall_f_.assign(std::size_t(K) * (p_.size() - nm_), Vec3::Zero());
    for (long s0 = 0; s0 < steps; s0 += K) {
      const long k_sweep = std::min(K, steps - s0);
      if (timed_update() || need_.empty()) measure_need();
      std::vector<std::size_t> drifted(std::size_t(k_sweep), 0), done(std::size_t(k_sweep), 0);
      std::vector<Totals> t(static_cast<std::size_t>(k_sweep));
      std::fill(wall_f_.begin(), wall_f_.end(), Vec3::Zero());
      while (done[std::size_t(k_sweep - 1)] < nb_) {
        for (std::size_t k = 0; k < std::size_t(k_sweep); ++k) {
          const std::size_t stride = std::size_t(K);
          Vec3* wall_f = wall_f_.data() + k;  // wall j's sum of step k at (j - nm) * K + k
          while (done[k] < nb_) {
            const std::size_t target = need_[done[k]];
            while (drifted[k] <= target && (k == 0 || done[k - 1] > drifted[k])) {
              const std::size_t b = drifted[k]++;
              for (std::size_t i = b * kBlock, e = std::min(nm_, i + kBlock); i < e; ++i) {
                drift(i);
                p_.f[i] = Vec3::Zero();
              }
            }
            if (drifted[k] <= target) break;
            const std::size_t b = done[k]++;
            (prefetch && k == 0) ? forces<true>(b, wall_f, stride, t[k]) : forces<false>(b, wall_f, stride, t[k]);
            for (std::size_t i = b * kBlock, e = std::min(nm_, i + kBlock); i < e; ++i) kick(i);
            if (k == 0) break;  // the leading step moves one block per round
          }
        }
        window_sum_ += double(drifted[0] - done[std::size_t(k_sweep - 1)]);
        ++window_rounds_;
      }
      // The walls' loads of the sweep's last step, where the plain loop leaves them.
      for (std::size_t j = nm_; j < p_.size(); ++j) p_.f[j] = wall_f_[(j - nm_) * std::size_t(K) + std::size_t(k_sweep - 1)];
      last_ = t.back();
    }
  }

  const Totals& last() const { return last_; }
  double list_seconds() const { return list_seconds_; }
  /// Blocks from the last step's next force block to the leading step's drift, on average.
  double mean_window() const { return window_rounds_ ? window_sum_ / double(window_rounds_) : 0.0; }
  std::size_t mean_need_blocks() const {
    std::size_t s = 0;
    for (std::size_t b = 0; b < need_.size(); ++b) s += need_[b] - b;
    return need_.empty() ? 0 : s / need_.size();
  }

 private:
  bool timed_update() {
    const auto t0 = std::chrono::steady_clock::now();
    const bool built = list_.update(p_);
    list_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return built;
  }
  void drift(std::size_t i) {
    vh_[i] = p_.v[i] + 0.5 * dt_ * a_[i];
    p_.x[i] += dt_ * vh_[i];
    p_.v[i] = vh_[i];  // the half-step dashpot velocity
  }
  void kick(std::size_t i) {
    a_[i] = p_.f[i] / p_.m[i] + g_;
    p_.v[i] = vh_[i] + 0.5 * dt_ * a_[i];
  }

  /// Per block: the highest block a mobile neighbour of its balls lies in.
  void measure_need() {
    need_.assign(nb_, 0);
    for (std::size_t b = 0; b < nb_; ++b) {
      std::size_t hi = b;
      for (std::size_t s = list_.begin(b * kBlock), e = list_.begin(std::min(nm_, (b + 1) * kBlock)); s < e; ++s)
        if (list_.neighbour(s) < nm_) hi = std::max(hi, std::size_t(list_.neighbour(s)) / kBlock);
      need_[b] = hi;
    }
  }

  /// The solver's chunk: select the touching slots, then the law on them, reactions scattered.
  template <bool Prefetch>
  void forces(std::size_t b, Vec3* wall_f, std::size_t wall_stride, Totals& t) {
    const std::size_t s0 = list_.begin(b * kBlock), s1 = list_.begin(std::min(nm_, (b + 1) * kBlock));
    if (sel_.size() < s1 - s0) sel_.resize(s1 - s0);
    std::size_t n = 0;
    const std::size_t ahead = std::min<std::size_t>(list_.front(), 16384) + 64;
    const char* base[8] = {(const char*)p_.x.data(), (const char*)p_.f.data(), (const char*)p_.v.data(), (const char*)p_.x.data(),
                           (const char*)p_.r.data(), (const char*)p_.k.data(), (const char*)p_.c.data(), (const char*)p_.f.data()};
    const std::size_t stride[8] = {24, 24, 24, 24, 8, 8, 8, 24};
    unsigned at = 0;
    for (std::size_t s = s0; s < s1; ++s) {
      sel_[n] = std::uint32_t(s);
      const std::uint32_t i = list_.owner(s), j = list_.neighbour(s);
      if constexpr (Prefetch) {
        __builtin_prefetch(base[at] + std::min(i + ahead, nm_ - 1) * stride[at]);
        at = (at + 1) & 7u;
      }
      const double touch = p_.r[i] + p_.r[j];
      n += std::size_t((p_.x[i] - p_.x[j]).squaredNorm() < touch * touch);
    }
    Vec3* f = p_.f.data();
    for (std::size_t q = 0; q < n; ++q) {
      const std::size_t s = sel_[q];
      const std::uint32_t i = list_.owner(s), j = list_.neighbour(s);
      const Vec3 d = p_.x[i] - p_.x[j];
      const double dist = std::sqrt(d.squaredNorm());
      const double delta = p_.r[i] + p_.r[j] - dist;
      const double k = contact::series(p_.k[i], p_.k[j]);
      const Vec3 nrm = d * (1.0 / dist);
      const double rate = -(p_.v[i] - p_.v[j]).dot(nrm);
      const double c = contact::series(p_.c[i], p_.c[j]);
      const contact::PairForce pf = contact::kelvin_voigt<true>(k, c, delta, rate);
      t.elastic += pf.elastic;
      t.dissipated += pf.p_dissipated;
      ++t.contacts;
      const Vec3 fij = pf.f * nrm;
      f[i] += fij;
      (j < nm_ ? f[j] : wall_f[(j - nm_) * wall_stride]) -= fij;
    }
  }

  Particles& p_;
  NeighbourList& list_;
  double dt_;
  Vec3 g_;
  std::size_t nm_, nb_;
  std::vector<Vec3> a_, vh_;
  std::vector<Vec3> wall_f_;
  std::vector<std::size_t> need_;
  std::vector<std::uint32_t> sel_;
  Totals last_;
  double list_seconds_ = 0.0, window_sum_ = 0.0;
  long window_rounds_ = 0;
};

Particles prepared(const CaseConfig& cfg) {
  Scene scene = build_scene(cfg);
  Particles p = scene.particles;
  if (p.n_mobile == 0) throw std::invalid_argument(cfg.name + ": no mobile balls to step");
  const double r_min = *std::min_element(p.r.begin(), p.r.begin() + long(p.n_mobile));
  p.permute_mobile(sweep_order(p, 2.0 * r_min));
  return p;
}

bool same_bits(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0;
}

}  // namespace

int run(int argc, char** argv) {
  const bool check = argc > 1 && std::strcmp(argv[1], "--check") == 0;
  if (argc < 5) {
    std::fprintf(stderr, "usage: %s CASE.json STEPS ROUNDS K... | --check CASE.json STEPS K\n", argv[0]);
    return 2;
  }
  const int a0 = check ? 2 : 1;
  const CaseConfig cfg = load_case_file(argv[a0]);
  if (cfg.contact.cohesion || cfg.contact.onset_correction || !cfg.contact.clamp ||
      cfg.integrator.scheme != Scheme::VelocityVerlet || !cfg.integrator.half_step_dashpot)
    throw std::invalid_argument(cfg.name + ": the model runs only the scaling beds' law and scheme (clamped Kelvin-Voigt, "
                                "no cohesion, no onset correction, velocity Verlet with the half-step dashpot)");
  const long steps = std::atol(argv[a0 + 1]);
  if (steps <= 0) throw std::invalid_argument("STEPS must be a positive integer");
  const Particles start = prepared(cfg);
  const bool hints = std::getenv("NOPREFETCH") == nullptr && start.n_mobile >= 50000;  // as the solver
  const double per = 1e9 / double(steps) / double(start.n_mobile);
  if (check) {
    const long K = std::atol(argv[a0 + 2]);
    if (K <= 0) throw std::invalid_argument("--check needs K >= 1");
    Particles p = start, q = start;
    NeighbourList list_p(cfg.skin, 0.0), list_q(cfg.skin, 0.0);
    Stepper wave(p, list_p, cfg.dt, cfg.gravity), plain(q, list_q, cfg.dt, cfg.gravity);
    wave.wavefront_steps(steps, K, hints);
    plain.plain_steps(steps, K, Stepper::Check::BeforeDrift, hints);
    const bool ok = same_bits(p.x, q.x) && same_bits(p.v, q.v) && same_bits(p.f, q.f) &&
                    wave.last().elastic == plain.last().elastic && wave.last().contacts == plain.last().contacts;
    std::printf("%s: %ld steps, K = %ld, against the plain loop with the list checked every %ld steps (builds %zu, %zu): %s\n",
                cfg.name.c_str(), steps, K, K, list_p.builds(), list_q.builds(), ok ? "bitwise the same" : "DIFFERENT");
    // The model's plain loop against the solver's own force field and integrator (list checked
    // every step, one thread): the copy of the loop above must be the solver's, bit for bit.
    Particles m = start, r = start;
    NeighbourList list_m(cfg.skin, 0.0), list_r(cfg.skin, 0.0);
    Stepper model(m, list_m, cfg.dt, cfg.gravity);
    model.plain_steps(steps, 1, Stepper::Check::AfterDrift, hints);
    set_threads(1);
    const auto field = make_force_field(cfg.contact, cfg.gravity.norm(), cfg.dt);
    const auto integrator = make_integrator(cfg.integrator, cfg.gravity);
    const ForceEvaluation eval = [&](Particles& x) {
      list_r.update(x);
      return field->compute(x, list_r);
    };
    for (long s = 0; s < steps; ++s) integrator->step(r, eval, cfg.dt);
    const bool same_as_solver = same_bits(m.x, r.x) && same_bits(m.v, r.v) && same_bits(m.f, r.f);
    std::printf("%s: %ld steps, the model's plain loop against the solver's ForceField and VelocityVerlet: %s\n",
                cfg.name.c_str(), steps, same_as_solver ? "bitwise the same" : "DIFFERENT");
    return ok && same_as_solver ? 0 : 1;
  }
  const long rounds = std::atol(argv[a0 + 2]);
  if (rounds <= 0) throw std::invalid_argument("ROUNDS must be a positive integer");
  std::vector<long> ks;
  for (int a = a0 + 3; a < argc; ++a) ks.push_back(std::atol(argv[a]));
  for (const long k : ks)
    if (k < 0) throw std::invalid_argument("K must be >= 0");
  std::vector<double> best(ks.size(), 1e300), best_nolist(ks.size(), 1e300);
  for (long r = 0; r < rounds; ++r)
    for (std::size_t v = 0; v < ks.size(); ++v) {
      Particles p = start;
      NeighbourList list(cfg.skin, 0.0);
      Stepper st(p, list, cfg.dt, cfg.gravity);
      const auto t0 = std::chrono::steady_clock::now();
      ks[v] == 0 ? st.plain_steps(steps, 1, Stepper::Check::AfterDrift, hints) : st.wavefront_steps(steps, ks[v], hints);
      const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      best[v] = std::min(best[v], sec * per);
      best_nolist[v] = std::min(best_nolist[v], (sec - st.list_seconds()) * per);
      std::printf("%s N=%zu round %ld K=%ld: %.2f ns per ball-step, %.2f without the list (%zu builds), contacts %.3f, "
                  "slots %.3f per ball, need %zu blocks, window %.1f blocks\n",
                  cfg.name.c_str(), start.n_mobile, r, ks[v], sec * per, (sec - st.list_seconds()) * per, list.builds(),
                  double(st.last().contacts) / double(start.n_mobile), double(list.pair_count()) / double(start.n_mobile),
                  st.mean_need_blocks(), st.mean_window());
      std::fflush(stdout);
    }
  for (std::size_t v = 0; v < ks.size(); ++v)
    std::printf("MIN %s N=%zu K=%ld: %.2f ns per ball-step, %.2f without the list\n", cfg.name.c_str(), start.n_mobile, ks[v],
                best[v], best_nolist[v]);
  return 0;
}

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_wavefront_model: %s\n", e.what());
    return 1;
  }
}
