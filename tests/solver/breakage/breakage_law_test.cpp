// Seed 003's breakage model (docs/model.md §14) against its own closed forms (notes V6 (b), (c)):
// the toughness hazard, P(broken | E_cum) = 1 − exp(−S E_cum), over 10^5 grains within 4 binomial
// σ, both from the law and through the stage fed synthetic contact ends; the fragment count's
// histogram against the clipped, rounded normal law (χ², 5 cells); one break keeps Σ r³ and the
// momentum to 1e-12 and gives each fragment the parent's rigid-body velocity at its centre.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "silodem/breakage/breakage_law.hpp"
#include "silodem/breakage/breakage_stage.hpp"

using namespace silodem;

namespace {

/// |fraction − p| within 4 binomial σ of n trials.
void expect_binomial(long hits, long n, double p) {
  const double sigma = std::sqrt(p * (1.0 - p) / double(n));
  EXPECT_NEAR(double(hits) / double(n), p, 4.0 * sigma) << hits << " of " << n;
}

BreakageSpec ore_spec(double strength, double e_min) {
  BreakageSpec b;
  b.materials = {"ore"};
  b.strength = strength;
  b.minimum_energy = e_min;
  return b;
}

}  // namespace

TEST(BreakageLaw, ToughnessGivesTheExponentialHazardWhateverTheCheckCount) {
  constexpr long kGrains = 100000;
  constexpr double kS = 0.01, kDeltaE = 20.0;  // each event adds ΔE beyond E_min
  for (const int events : {1, 3, 8}) {
    long broken = 0;
    for (long tag = 1; tag <= kGrains; ++tag) {
      double e_cum = 0.0;
      for (int k = 0; k < events; ++k) e_cum += breakage::energy_increment(25.0 + kDeltaE, 25.0, 0.1, 0.1, 0.0);
      broken += e_cum >= breakage::toughness(7, tag, kS);
    }
    // Checked after every event or once at the end: the same grains, 1 − exp(−S n ΔE) of them (not
    // the thesis code's 1 − exp(−S ΔE n(n+1)/2), notes B7).
    expect_binomial(broken, kGrains, 1.0 - std::exp(-kS * events * kDeltaE));
  }
}

TEST(BreakageLaw, EnergyBelowTheMinimumCountsNothingAndTheMinimumScalesWithSize) {
  EXPECT_EQ(breakage::energy_increment(20.0, 25.0, 0.1, 0.1, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(breakage::energy_increment(30.0, 25.0, 0.1, 0.1, 0.0), 5.0);
  EXPECT_DOUBLE_EQ(breakage::energy_increment(30.0, 25.0, 0.05, 0.1, 1.0), 17.5);  // E_min 12.5 at half size (the code's law)
}

TEST(BreakageStage, SyntheticContactEndsBreakTheFractionTheHazardGives) {
  // 20,000 ore grains in pairs; each pair's contact ends three times with E = E_min + ΔE.
  constexpr std::size_t kGrains = 20000;
  constexpr double kS = 0.02, kEmin = 10.0, kDeltaE = 15.0;
  Particles p;
  for (std::size_t i = 0; i < kGrains; ++i)
    p.add({Vec3(double(i), 0, 0), Vec3::Zero(), 0.1, 1.0, 0.0, 0.0, 0, "g" + std::to_string(i), std::int64_t(i + 1)}, false);
  BreakageStage stage(ore_spec(kS, kEmin), 11, {"ore"});
  std::vector<ContactEnd> ends;
  for (std::size_t i = 0; i < kGrains; i += 2) ends.push_back({std::int64_t(i + 1), std::int64_t(i + 2), kEmin + kDeltaE});
  for (int round = 0; round < 3; ++round) stage.absorb(ends, p);
  const auto born = stage.break_due(p, 0.0);
  const long breaks = stage.summary()["breaks"].get<long>();
  expect_binomial(breaks, long(kGrains), 1.0 - std::exp(-kS * 3.0 * kDeltaE));
  // Mass: every break kept its grain's mass among its fragments.
  double mass = 0.0;
  for (std::size_t i = 0; i < p.n_mobile; ++i) mass += p.m[i];
  EXPECT_NEAR(mass, double(kGrains), 1e-9 * double(kGrains));
  EXPECT_EQ(p.n_mobile, kGrains - std::size_t(breaks) + born.size());
}

TEST(BreakageLaw, FragmentCountsFollowTheClippedRoundedNormal) {
  constexpr long kDraws = 100000;
  constexpr double kMean = 4.0, kSd = 2.0 / 3.0;
  std::array<long, 5> seen{};
  for (long tag = 1; tag <= kDraws; ++tag) ++seen[std::size_t(breakage::fragment_count(3, tag, kMean, kSd, 2, 6) - 2)];
  const auto cdf = [&](double x) { return 0.5 * std::erfc(-(x - kMean) / (kSd * std::sqrt(2.0))); };
  double chi2 = 0.0;
  for (int n = 2; n <= 6; ++n) {
    const double lo = n == 2 ? 0.0 : cdf(n - 0.5), hi = n == 6 ? 1.0 : cdf(n + 0.5);
    const double expected = double(kDraws) * (hi - lo);
    chi2 += std::pow(double(seen[std::size_t(n - 2)]) - expected, 2) / expected;
  }
  EXPECT_LT(chi2, 13.28) << "chi-squared of 4 degrees of freedom above its 1 % point";
}

TEST(BreakageLaw, OneBreakKeepsVolumeAndMomentumAndGivesTheRigidVelocityField) {
  const Vec3 x(0.3, -0.1, 2.0), v(1.5, 0.0, -2.0), w(0.0, 7.0, 0.0);
  constexpr double kR = 0.1;
  for (int n = 2; n <= 6; ++n) {
    const auto parts = breakage::fragments(x, v, w, kR, n, Vec3::UnitY(), Vec3::UnitX());
    ASSERT_EQ(parts.size(), std::size_t(n));
    double volume = 0.0;
    Vec3 momentum = Vec3::Zero(), centre = Vec3::Zero();
    for (const auto& f : parts) {
      volume += std::pow(f.r, 3);
      momentum += f.v / double(n);  // equal masses, M/n each
      centre += f.x / double(n);
      EXPECT_NEAR((f.x - x).norm() + f.r, kR, 1e-15 * 10) << "each fragment touches the parent's surface from inside";
      EXPECT_NEAR((f.v - (v + w.cross(f.x - x))).norm(), 0.0, 1e-14);
      EXPECT_EQ(f.w, w);
      EXPECT_NEAR(f.x.y(), x.y(), 1e-14) << "the ring lies in the x-z plane";
    }
    EXPECT_NEAR(volume, kR * kR * kR, 1e-12 * kR * kR * kR);
    EXPECT_NEAR((momentum - v).norm(), 0.0, 1e-12 * v.norm());
    EXPECT_NEAR((centre - x).norm(), 0.0, 1e-12);
  }
}
