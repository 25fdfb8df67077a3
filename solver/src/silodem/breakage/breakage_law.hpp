#pragma once
// Seed 003's breakage model as the notes read it (docs/model.md §14; Katnov 2021, (34)–(36), and
// the notes' readings B7–B11): small functions of one grain, no loop mechanics. The stage that
// applies them to a run is breakage/breakage_stage.hpp.
#include <cstdint>
#include <vector>

#include "silodem/core/types.hpp"

namespace silodem::breakage {

/// A uniform variate on (0, 1) that depends only on (seed, tag, stream): a grain's draws do not
/// depend on the order in which grains break, on threads, or on a restart (SplitMix64 mixing).
double uniform_for(std::uint64_t seed, std::int64_t tag, std::uint64_t stream);

/// A grain's toughness E_b ~ Exponential(rate S), J: it breaks once E_cum ≥ E_b, so
/// P(broken | E_cum) = 1 − exp(−S E_cum) exactly, however often it is checked (notes B7, (36)).
double toughness(std::uint64_t seed, std::int64_t tag, double strength);

/// What one ended contact adds to a grain's E_cum: (E − E_min)₊ (34), with E_min scaled by
/// (r / r_original)^size_exponent (notes B9).
double energy_increment(double contact_energy, double minimum_energy, double radius, double original_radius,
                        double size_exponent);

/// The number of fragments: round(N(mean, sd)) clipped to [lo, hi] (the text's law, notes B10),
/// from the grain's own draws (Box–Muller on two uniforms of its tag).
int fragment_count(std::uint64_t seed, std::int64_t tag, double mean, double sd, int lo, int hi);

struct Fragment {
  Vec3 x, v, w;
  double r;
};

/// The parent (centre x, velocity v, spin w, radius r) as `n` equal fragments of radius r n^(−1/3)
/// (Σ r_f³ = r³: mass kept at one density), centres on a ring of radius r − r_f about x in the
/// plane normal to `ring_normal`, at angles 2πk/n from `ring_start` (notes II.1.10). Each takes the
/// parent's rigid-body velocity at its centre, v + w × (x_f − x), and its spin w: linear momentum
/// is kept exactly (the ring's moments cancel), the kinetic energy to within what the rigid field
/// gives (notes B11).
std::vector<Fragment> fragments(const Vec3& x, const Vec3& v, const Vec3& w, double r, int n, const Vec3& ring_normal,
                                const Vec3& ring_start);

}  // namespace silodem::breakage
