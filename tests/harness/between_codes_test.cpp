// How silodem's side of a between-codes row is taken (docs/case-format.md, compare.between_codes):
// from its own probes (default), at a reference code's dump frames (`silodem_sampled`), or as the
// mean of its realisations (`silodem_value`); and the refusal of values these keys do not take.
// The runs need LAMMPS (tools/setup.sh installs it).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/compare.hpp"
#include "silodem/case/case_error.hpp"
#include "compare_scratch.hpp"
#include "scratch_case.hpp"

namespace fs = std::filesystem;

namespace {

/// A grain of r = 2 cm set down at height z on a small floor of wall balls (radii drawn from
/// `radius` by the seed, `spacing` apart), linear law, velocity Verlet, 1.2 ms; the floor's pressure
/// probed in one cell. The caller adds the compare section.
nlohmann::json grain_on_floor(const std::string& name, std::vector<double> radius, double spacing, double z) {
  return {
      {"name", name},
      {"gravity", {0, 0, -9.81}},
      {"materials",
       {{"grain", {{"density", 2500.0}, {"stiffness", 1e6}, {"restitution", 0.3}, {"reference_radius", 0.02}}},
        {"wall", {{"density", 7800.0}, {"stiffness", 1e6}, {"damping", 50.0}}}}},
      {"walls", {{{"name", "floor"}, {"type", "disk"}, {"material", "wall"}, {"radius", radius},
                  {"spacing", spacing}, {"centre", {0, 0, 0}}, {"diameter", 0.03}}}},
      {"balls", {{{"id", "grain"}, {"material", "grain"}, {"radius", 0.02}, {"position", {0, 0, z}}}}},
      {"integrator", {{"scheme", "velocity_verlet"}, {"dashpot_velocity", "half_step"}}},
      {"time", {{"dt", 1e-5}, {"duration", 1.2e-3}}},
      {"output", {{"probes", {{{"type", "wall_pressure"}, {"name", "floor"}, {"wall", "floor"}, {"angle_bins", 1}, {"height_bins", 1}}}}}}};
}

}  // namespace

// A reference code is known only at its dump frames, the last of them up to one interval before the
// run's end; silodem's own probes see every step. With `silodem_sampled: "at_frames"` silodem is
// held against a code at that code's frames: its rows rebuilt from its own dump. A grain set down
// touching one wall ball sinks and swings on it (period 2π√(m/k) = 1.8 ms, damped); the run ends at
// step 120, the last frame is step 100, and the floor's pressure there is 6 % below the end's
// (measured). LAMMPS runs the same scheme and law, so at the same frame the two are round-off apart.
TEST(BetweenCodes, SilodemIsHeldAgainstACodeAtThatCodesDumpFrames) {
  nlohmann::json c = grain_on_floor("frames", {0.005, 0.005}, 0.006, 0.02);
  c["output"]["dump_interval_steps"] = 50;
  c["compare"] = {
      {"codes", {"silodem", "lammps"}},
      {"checks", {{{"type", "pressure_profile"}, {"wall_probe", "floor"}, {"value", "final"}}}},
      {"between_codes",
       {{{"quantity", "band_pressure"}, {"tolerance", 1e-9}, {"relative_to", "largest"}, {"silodem_sampled", "at_frames"},
         {"tolerance_source", {{"type", "scheme_bound"}, {"derivation", "the same scheme and law at the same frame: round-off apart"}}}}}}};
  const fs::path dir = test_scratch::with_case("silodem_test_frames", "frames.json", c);
  const auto v = test_scratch::compare_scratch(dir, "frames.json", "out");
  double own = 0.0;
  const harness::CheckRow* between = nullptr;
  for (const auto& r : v.rows) {
    if (r.quantity != "band_pressure") continue;
    if (r.code == "silodem") own = r.measured;
    if (r.code == "silodem vs lammps") between = &r;
  }
  ASSERT_NE(between, nullptr);
  ASSERT_GT(own, 0.0);
  EXPECT_TRUE(between->judged());
  EXPECT_TRUE(between->pass) << between->measured << " vs " << between->expected << " " << between->note;
  EXPECT_LT(std::abs(between->error), 1e-9) << between->note;
  EXPECT_NE(between->note.find("silodem at the dump frames"), std::string::npos) << between->note;
  // The last step is not the last frame: silodem's own final differs from its frame's by far more.
  EXPECT_GT(std::abs(own / between->measured - 1.0), 0.03) << own << " vs " << between->measured;
}

// A time mean over a chaotic flow is one realisation per run; with `silodem_value: "seeds_mean"` a
// code is held against the mean of silodem's realisations (its run and one per seed). The grain of
// the test above, set down overlapping a floor whose ball radii the seed draws, is thrown off with
// another overlap for each seed, so each gives another mean floor pressure; the row's silodem value is the mean of the three read from their probe files.
TEST(BetweenCodes, AChaoticMeanIsHeldAgainstTheMeanOfSilodemsRealisations) {
  nlohmann::json c = grain_on_floor("mean", {0.0045, 0.005}, 0.0085, 0.0185);
  c["compare"] = {
      {"codes", {"silodem", "lammps"}},
      {"seeds", {5, 6}},
      {"checks", {{{"type", "pressure_profile"}, {"wall_probe", "floor"}, {"value", "mean"}}}},
      {"between_codes", {{{"quantity", "band_pressure"}, {"relative_to", "largest"}, {"silodem_value", "seeds_mean"},
                          {"report", "a plumbing test"}}}}};
  const fs::path dir = test_scratch::with_case("silodem_test_seeds_mean", "mean.json", c);
  const auto v = test_scratch::compare_scratch(dir, "mean.json", "out");
  const harness::CheckRow* between = nullptr;
  for (const auto& r : v.rows)
    if (r.quantity == "band_pressure" && r.code == "silodem vs lammps") between = &r;
  ASSERT_NE(between, nullptr);
  const auto mean_pressure = [&](const std::string& run) {
    std::ifstream in(dir / "out" / "mean" / "base" / run / "probes" / "floor.csv");
    std::string header, row;
    std::getline(in, header);
    std::getline(in, row);
    std::vector<std::string> names, cells;
    for (std::stringstream h(header); std::getline(h, names.emplace_back(), ',');) {}
    for (std::stringstream r(row); std::getline(r, cells.emplace_back(), ',');) {}
    for (std::size_t k = 0; k < names.size(); ++k)
      if (names[k] == "pressure_mean") return std::stod(cells.at(k));
    return std::nan("");
  };
  const double p0 = mean_pressure("silodem"), p5 = mean_pressure("silodem_seed5"), p6 = mean_pressure("silodem_seed6");
  ASSERT_TRUE(p0 > 0.0 && p5 > 0.0 && p6 > 0.0) << p0 << " " << p5 << " " << p6;
  EXPECT_GT(std::max({p0, p5, p6}) - std::min({p0, p5, p6}), 1e-3 * p0) << "the seeds give other floors";
  EXPECT_NEAR(between->measured, (p0 + p5 + p6) / 3.0, 1e-9 * p0) << between->note;
  EXPECT_NE(between->note.find("the mean of its 3 realisations"), std::string::npos) << between->note;
}

/// collision_restitution.json with its first between_codes entry's `key` set to `value` (and without
/// compare.seeds when `drop_seeds`): the message of the CaseError that validation must throw.
static std::string refusal(const std::string& key, const std::string& value, bool drop_seeds = false) {
  std::ifstream in(std::string(SILODEM_SOURCE_DIR) + "/cases/collision_restitution.json");
  nlohmann::json c = nlohmann::json::parse(in);
  if (drop_seeds) c["compare"].erase("seeds");
  c["compare"]["between_codes"][0][key] = value;
  const fs::path dir = test_scratch::with_case("silodem_test_between_refused", "case.json", c);
  try {
    harness::validate_comparison(dir / "case.json");
  } catch (const silodem::CaseError& e) {
    return e.what();
  }
  return "accepted";
}

// "seeds_mean" needs realisations: without compare.seeds it is refused at load, with its path.
TEST(BetweenCodes, ASeedsMeanWithoutSeedsIsRefused) {
  const std::string why = refusal("silodem_value", "seeds_mean", true);
  EXPECT_NE(why.find("between_codes[0].silodem_value"), std::string::npos) << why;
}

// silodem_sampled takes one of its two values; anything else is refused at load, with its path.
TEST(BetweenCodes, AnUnknownSamplingOfSilodemIsRefused) {
  const std::string why = refusal("silodem_sampled", "sometimes");
  EXPECT_NE(why.find("between_codes[0].silodem_sampled"), std::string::npos) << why;
}
