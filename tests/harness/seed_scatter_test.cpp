// Seed scatter (harness/seed_scatter.cpp): mean and sample standard deviation over the
// realisations, on the between_codes scale of each quantity, and the note on the between rows.
#include <gtest/gtest.h>

#include <cmath>

#include "harness/seed_scatter.hpp"

using harness::CheckRow;

namespace {
CheckRow row(const std::string& q, const std::string& subject, double measured) {
  CheckRow r;
  r.case_name = "c";
  r.variant = "base";
  r.quantity = q;
  r.subject = subject;
  r.measured = measured;
  return r;
}
}  // namespace

TEST(SeedScatter, SampleStdOnTheBetweenCodesScale) {
  const std::vector<CheckRow> main_rows = {row("band_pressure", "mantle band 0", 100.0), row("band_pressure", "mantle band 1", 10.0),
                                           row("mass_flow_rate", "outlet", 0.60)};
  const std::vector<std::vector<CheckRow>> seeds = {
      {row("band_pressure", "mantle band 0", 110.0), row("band_pressure", "mantle band 1", 12.0), row("mass_flow_rate", "outlet", 0.66)},
      {row("band_pressure", "mantle band 0", 90.0), row("band_pressure", "mantle band 1", 8.0), row("mass_flow_rate", "outlet", 0.63)}};
  const auto rows = harness::seed_scatter_rows(
      {{"band_pressure", harness::DifferenceScale::LargestOfProfile}, {"mass_flow_rate", harness::DifferenceScale::Value}},
      main_rows, seeds, "seeds 1, 2, 3");
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].code, "silodem seeds");
  for (const auto& r : rows) EXPECT_EQ(r.verdict(), "report");  // a measurement, the yardstick, not a verdict
  EXPECT_DOUBLE_EQ(rows[0].expected, 100.0);
  EXPECT_NEAR(rows[0].measured, 10.0, 1e-12);           // sample std of 100, 110, 90
  EXPECT_NEAR(rows[0].error, 10.0 / 100.0, 1e-12);      // / the largest mean of the profile
  EXPECT_NEAR(rows[1].measured, 2.0, 1e-12);
  EXPECT_NEAR(rows[1].error, 2.0 / 100.0, 1e-12);       // band 1 on band 0's scale
  EXPECT_NEAR(rows[2].expected, 0.63, 1e-12);
  EXPECT_NEAR(rows[2].error, 0.03 / 0.63, 1e-12);       // / |mean|

  std::vector<CheckRow> between = {row("mass_flow_rate", "outlet", 0.62)};
  between[0].error = 0.06;
  harness::annotate_with_scatter(between, rows);
  EXPECT_NE(between[0].note.find("|difference|/scatter = 1.26"), std::string::npos) << between[0].note;
}

// Two checks that give the same quantity and subject (janssen's and static_balance's wall load) make
// one scatter row over one value per realisation, not twice as many values.
TEST(SeedScatter, OneValuePerRealisationWhenTwoChecksGiveTheSameRow) {
  const std::vector<CheckRow> main_rows = {row("wall_load/weight", "all walls", 1.0), row("wall_load/weight", "all walls", 1.0)};
  const std::vector<std::vector<CheckRow>> seeds = {
      {row("wall_load/weight", "all walls", 1.2), row("wall_load/weight", "all walls", 1.2)},
      {row("wall_load/weight", "all walls", 0.8), row("wall_load/weight", "all walls", 0.8)}};
  const auto rows = harness::seed_scatter_rows({{"wall_load/weight", harness::DifferenceScale::Value}}, main_rows, seeds,
                                               "seeds 1, 2, 3");
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_NEAR(rows[0].measured, 0.2, 1e-12);  // sample std of 1.0, 1.2, 0.8 (five values would give 0.158)
  EXPECT_NE(rows[0].note.find("over 3 realisations"), std::string::npos) << rows[0].note;
}
