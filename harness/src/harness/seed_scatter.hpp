#pragma once
// Seed scatter: the yardstick for differences between codes (silo issue: "difference per height
// band, with the scatter between seeds as the yardstick"). Every code starts from one shared
// state, so their differences come from integration and contact law only; silodem alone also
// continues from the states other seeds give (another wall roughness, hence another packing), and
// the spread of a quantity over those realisations says how much a difference between codes
// would matter next to the run-to-run scatter a silo engineer sees anyway.
#include <map>
#include <string>
#include <vector>

#include "harness/checks.hpp"

namespace harness {

/// How a between_codes row scales its difference; the scatter row uses the same scale.
enum class DifferenceScale { Value, LargestOfProfile, Absolute };

struct ScatterQuantity {
  std::string quantity;
  DifferenceScale scale = DifferenceScale::Value;
};

/// Rows of the profile "mantle band 3" share a scale with the other bands of "mantle".
std::string profile_of(const std::string& subject);

/// One row per subject of each quantity: expected = the mean over the realisations (the main
/// run first, then one per extra seed), measured = their sample standard deviation, error = that
/// deviation on the between_codes scale. A report row: a measurement, not a test.
std::vector<CheckRow> seed_scatter_rows(const std::vector<ScatterQuantity>& quantities, const std::vector<CheckRow>& main_rows,
                                        const std::vector<std::vector<CheckRow>>& seed_rows,
                                        const std::string& seeds_label);

/// Adds "seed scatter σ; |difference|/σ" to the note of each between_codes row whose quantity and
/// subject have a scatter row.
void annotate_with_scatter(std::vector<CheckRow>& between_rows, const std::vector<CheckRow>& scatter_rows);

}  // namespace harness
