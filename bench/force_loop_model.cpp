// A stand-alone model of the force loop's memory traffic (forces/force_field.cpp), to tell what
// in the growth of its cost with N belongs to the access pattern on this machine rather than to
// the solver (reports/perf_experiments.md, eleventh session). Synthetic data, no physics.
//
//   tools/build.sh && taskset -c 0 build/bench/bench_force_loop_model MODE
//   (prints ns per ball at 5,000 and 10^6 balls; the eleventh session's figures came from a
//   stand-alone g++ -O2 build, the tree builds -O3)
//
// What it keeps of the loop: seven per-ball arrays (x, v, f of 24 bytes; r, k, c, m of 8), a
// half list in slot order (owner and neighbour per slot, about 4.6 slots per ball, partners 1-2,
// 17-21, 290-310 and 580-582 balls ahead as in a swept bed), chunks of 1,180 slots, each a
// selection pass (x and r of both balls) and then a pass over the selected slots (every one here)
// that reads all seven arrays of both balls, two divisions for the series constants, a square
// root, and scatters the reaction onto the neighbour.
// MODE bits: 1 rotating prefetch hints one front ahead (as AheadHints); 2 no scatter onto the
// neighbour; 16 packed per-ball records ({x, r, v, m} in one 64-byte line, {k, c}) instead of
// seven arrays; 32 every partner within 1-8 balls (no far partner).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

namespace {

struct V {
  double a, b, c;
};
struct alignas(64) Packed {
  double xa, xb, xc, r, va, vb, vc, m;
};
struct KC {
  double k, c;
};

double run(std::size_t n, int mode) {
  const std::size_t pad = 4000, chunk = 1180, ahead = 664;
  std::vector<V> x(n + pad, V{1, 2, 3}), v(n + pad, V{0, 0, 0}), f(n + pad, V{0, 0, 0});
  std::vector<double> r(n + pad, 0.5), k(n + pad, 1.0), c(n + pad, 1.0), m(n + pad, 1.0);
  std::vector<Packed> packed(n + pad, Packed{1, 2, 3, 0.5, 0, 0, 0, 1});
  std::vector<KC> kc(n + pad, KC{1, 1});
  std::vector<std::uint32_t> owner, nb;
  std::mt19937 rng(1);
  const int offsets[] = {1, 2, 17, 18, 19, 290, 291, 307, 308, 580};
  for (std::size_t i = 0; i < n; ++i)
    for (const int o : offsets)
      if (rng() % 100 < 46) {
        owner.push_back(std::uint32_t(i));
        nb.push_back(std::uint32_t(i + ((mode & 32) ? 1 + o / 100 : o) + rng() % 3));
      }
  const std::size_t slots = owner.size();
  std::vector<std::uint32_t> selected(chunk);
  const bool pk = mode & 16;
  // Accessors over the two layouts: the same values either way.
  auto X = [&](std::size_t i) { return pk ? V{packed[i].xa, packed[i].xb, packed[i].xc} : x[i]; };
  auto Vel = [&](std::size_t i) { return pk ? V{packed[i].va, packed[i].vb, packed[i].vc} : v[i]; };
  auto R = [&](std::size_t i) { return pk ? packed[i].r : r[i]; };
  auto M = [&](std::size_t i) { return pk ? packed[i].m : m[i]; };
  auto K = [&](std::size_t i) { return pk ? kc[i].k : k[i]; };
  auto C = [&](std::size_t i) { return pk ? kc[i].c : c[i]; };
  // The rotating hints' eight arrays, fixed once as AheadHints fixes them: {base, stride}.
  struct Hint {
    const char* base;
    std::size_t stride;
  };
  const auto hint_of = [](const auto& a) { return Hint{reinterpret_cast<const char*>(a.data()), sizeof(a[0])}; };
  const Hint hints[8] = {pk ? hint_of(packed) : hint_of(x), hint_of(f), pk ? hint_of(kc) : hint_of(v),
                         pk ? hint_of(packed) : hint_of(x), pk ? hint_of(packed) : hint_of(r),
                         pk ? hint_of(kc) : hint_of(k), pk ? hint_of(f) : hint_of(c), pk ? hint_of(packed) : hint_of(m)};
  const std::size_t steps = std::max<std::size_t>(2, 4000000 / n);
  double sum = 0.0;
  const auto t0 = std::chrono::steady_clock::now();
  for (std::size_t step = 0; step < steps; ++step) {
    std::fill(f.begin(), f.end(), V{0, 0, 0});
    for (std::size_t c0 = 0; c0 < slots; c0 += chunk) {
      const std::size_t c1 = std::min(slots, c0 + chunk);
      std::size_t count = 0;
      unsigned rot = 0;
      for (std::size_t s = c0; s < c1; ++s) {
        const std::uint32_t i = owner[s], j = nb[s];
        if (mode & 1) {
          __builtin_prefetch(hints[rot].base + (i + ahead) * hints[rot].stride);
          rot = (rot + 1) & 7u;
        }
        selected[count] = std::uint32_t(s);
        const V xi = X(i), xj = X(j);
        const double dx = xi.a - xj.a, dy = xi.b - xj.b, dz = xi.c - xj.c, t = R(i) + R(j);
        count += (dx * dx + dy * dy + dz * dz) < t * t * 1e9;  // every slot passes
      }
      for (std::size_t q = 0; q < count; ++q) {
        const std::size_t s = selected[q];
        const std::uint32_t i = owner[s], j = nb[s];
        const V xi = X(i), xj = X(j), vi = Vel(i), vj = Vel(j);
        const double dx = xi.a - xj.a + 1e-3, dy = xi.b - xj.b, dz = xi.c - xj.c;
        const double d = std::sqrt(dx * dx + dy * dy + dz * dz);
        const double ks = K(i) * K(j) / (K(i) + K(j)), cs = C(i) * C(j) / (C(i) + C(j));
        const double rate = -((vi.a - vj.a) * dx + (vi.b - vj.b) * dy + (vi.c - vj.c) * dz) / d;
        const double fs = (ks * (R(i) + R(j) - d) + cs * rate) / d * (1.0 / M(i) + 1.0 / M(j)) * 1e-9;
        f[i].a += fs * dx, f[i].b += fs * dy, f[i].c += fs * dz;
        if (!(mode & 2)) f[j].a -= fs * dx, f[j].b -= fs * dy, f[j].c -= fs * dz;
      }
    }
    sum += f[n / 2].a;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  volatile double sink = sum;
  (void)sink;
  return seconds / double(steps * n) * 1e9;
}

}  // namespace

int main(int argc, char** argv) {
  const int mode = argc > 1 ? std::atoi(argv[1]) : 1;
  const double small = run(5000, mode), large = run(1000000, mode);
  std::printf("mode %d: %.1f ns per ball at 5,000, %.1f at 10^6 (+%.1f)\n", mode, small, large, large - small);
}
