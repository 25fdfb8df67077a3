#pragma once
// Reproducible random numbers: the standard distributions are implementation-defined, so the
// uniform variate is built from the raw 64-bit engine, identical on every platform for a seed.
#include <cstdint>
#include <random>
#include <sstream>
#include <string>

namespace silodem {

class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  /// Uniform on [0, 1), 53 random bits.
  double uniform() { return double(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

  /// The engine's state in the standard's text form (exact, portable).
  std::string state() const {
    std::ostringstream s;
    s << engine_;
    return s.str();
  }
  /// Returns false if `text` is not an engine state.
  bool set_state(const std::string& text) {
    std::istringstream s(text);
    std::mt19937_64 e;
    s >> e;
    if (s.fail()) return false;
    engine_ = e;
    return true;
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace silodem
