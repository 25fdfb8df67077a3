#include "silodem/breakage/breakage_law.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>  // cross products

namespace silodem::breakage {

namespace {
/// SplitMix64's finaliser (Steele, Lea & Flood 2014): a bijective mix of 64 bits.
std::uint64_t mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}
constexpr std::uint64_t kToughnessStream = 1, kCountStream = 2;
}  // namespace

double uniform_for(std::uint64_t seed, std::int64_t tag, std::uint64_t stream) {
  const std::uint64_t bits = mix(mix(mix(seed) ^ std::uint64_t(tag)) + stream * 0x9e3779b97f4a7c15ULL);
  return (double(bits >> 11) + 0.5) * 0x1.0p-53;  // never 0 or 1
}

double toughness(std::uint64_t seed, std::int64_t tag, double strength) {
  return -std::log(uniform_for(seed, tag, kToughnessStream)) / strength;
}

double energy_increment(double contact_energy, double minimum_energy, double radius, double original_radius,
                        double size_exponent) {
  const double e_min = size_exponent == 0.0 ? minimum_energy : minimum_energy * std::pow(radius / original_radius, size_exponent);
  return std::max(0.0, contact_energy - e_min);
}

int fragment_count(std::uint64_t seed, std::int64_t tag, double mean, double sd, int lo, int hi) {
  const double u1 = uniform_for(seed, tag, kCountStream), u2 = uniform_for(seed, tag, kCountStream + 1);
  const double normal = std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
  return std::clamp(int(std::lround(mean + sd * normal)), lo, hi);
}

std::vector<Fragment> fragments(const Vec3& x, const Vec3& v, const Vec3& w, double r, int n, const Vec3& ring_normal,
                                const Vec3& ring_start) {
  const double r_f = r / std::cbrt(double(n));
  const Vec3 e1 = ring_start.normalized(), e2 = ring_normal.normalized().cross(e1);
  std::vector<Fragment> out;
  out.reserve(std::size_t(n));
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * M_PI * double(k) / double(n);
    const Vec3 arm = (r - r_f) * (std::cos(a) * e1 + std::sin(a) * e2);
    out.push_back({x + arm, v + w.cross(arm), w, r_f});
  }
  return out;
}

}  // namespace silodem::breakage
