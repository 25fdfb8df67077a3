#pragma once
// Free fall onto a fixed sphere (docs/theory.md §3a): first contact when b² + z² = R², R = r_i + r_j,
// b the horizontal offset — plain geometry, independent of the solver's quadratic root (15).
#include <cmath>

namespace references {

/// Height of the falling centre above the obstacle centre at first contact, or NaN if it misses.
inline double contact_height_above(double b, double R) { return b < R ? std::sqrt(R * R - b * b) : NAN; }

/// Fall time from rest through height H.
inline double fall_time(double H, double g) { return std::sqrt(2.0 * H / g); }

}  // namespace references
