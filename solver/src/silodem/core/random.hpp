#pragma once
// Reproducible random numbers: the standard distributions are implementation-defined, so the
// uniform variate is built from the raw 64-bit engine, identical on every platform for a seed.
#include <cstdint>
#include <random>

namespace silodem {

class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  /// Uniform on [0, 1), 53 random bits.
  double uniform() { return double(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

 private:
  std::mt19937_64 engine_;
};

}  // namespace silodem
