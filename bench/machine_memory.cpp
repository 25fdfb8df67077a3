// The machine's memory hierarchy as the scaling benchmark meets it: streaming bandwidth and the
// latency of dependent loads against the working set's size. It tells where the caches end
// (reports/perf_experiments.md, eleventh session: why 5,000 balls run from cache and 10^5 from memory).
//
//   tools/build.sh && taskset -c 0 build/bench/bench_machine_memory
//   (the eleventh session's figures came from a stand-alone g++ -O2 build; the tree builds -O3)
//
// Bandwidth: b[i] = a[i] * s + b[i] over two arrays (two reads and one write per element), repeated
// until about 4 GB have moved. Latency: a random cyclic chain of one 8-byte pointer per 64-byte
// line, so every load waits for the one before; the figure is the mean time per load.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <numeric>
#include <random>
#include <vector>

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double stream_gb_per_s(std::size_t bytes_per_array) {
  const std::size_t n = bytes_per_array / sizeof(double);
  std::vector<double> a(n, 1.0), b(n, 2.0);
  const std::size_t reps = std::max<std::size_t>(3, (std::size_t(4) << 30) / (3 * bytes_per_array));
  const auto t0 = std::chrono::steady_clock::now();
  for (std::size_t r = 0; r < reps; ++r)
    for (std::size_t i = 0; i < n; ++i) b[i] = a[i] * 1.0001 + b[i];
  const double s = seconds_since(t0);
  volatile double sink = b[n / 2];
  (void)sink;
  return 3.0 * double(bytes_per_array) * double(reps) / s / 1e9;
}

double chase_ns(std::size_t bytes) {
  const std::size_t lines = bytes / 64, stride = 64 / sizeof(std::size_t);
  std::vector<std::size_t> next(lines * stride, 0), order(lines);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::shuffle(order.begin(), order.end(), std::mt19937(1));
  for (std::size_t k = 0; k < lines; ++k) next[order[k] * stride] = order[(k + 1) % lines] * stride;
  const std::size_t loads = 20000000;
  std::size_t q = order[0] * stride;
  const auto t0 = std::chrono::steady_clock::now();
  for (std::size_t k = 0; k < loads; ++k) q = next[q];
  const double s = seconds_since(t0);
  volatile std::size_t sink = q;
  (void)sink;
  return s / double(loads) * 1e9;
}

}  // namespace

int main() {
  std::printf("working set | stream (2 reads + 1 write), GB/s | dependent load, ns\n");
  for (const std::size_t kb : {64, 256, 1024, 2048, 4096, 8192, 16384, 32768, 131072, 524288}) {
    const std::size_t bytes = kb * 1024;
    std::printf("%8zu KB | %6.1f | %6.1f\n", kb, stream_gb_per_s(bytes / 2), chase_ns(bytes));
    std::fflush(stdout);
  }
}
