// A between_codes row judges silodem's value against a reference code's with the case's tolerance;
// a relative tolerance must never pass on a zero scale (two empty outflows are not an agreement).
#include <gtest/gtest.h>

#include <cmath>

#include "harness/between_codes.hpp"

namespace {

harness::CheckRow value(double v) {
  harness::CheckRow r;
  r.quantity = "mass_flow_rate";
  r.subject = "outlet";
  r.kind = harness::RowKind::Match;
  r.measured = v;
  return r;
}

harness::Between relative(double tolerance) {
  harness::Between b;
  b.quantity = "mass_flow_rate";
  b.tolerance = tolerance;
  b.source = "seed scatter (test)";
  return b;
}

harness::CheckRow row(const harness::Between& b, double theirs, double ours, double largest = 0.0) {
  return harness::between_row(b, "c", "base", "lammps", value(theirs), value(ours), largest);
}

}  // namespace

TEST(BetweenCodes, RelativeDifferenceIsJudgedAgainstTheReferenceValue) {
  const auto pass = row(relative(0.03), 0.90, 0.92);
  EXPECT_EQ(pass.code, "silodem vs lammps");
  EXPECT_NEAR(pass.error, 0.02 / 0.90, 1e-15);
  EXPECT_EQ(pass.verdict(), "pass");
  EXPECT_EQ(row(relative(0.03), 0.90, 0.95).verdict(), "fail");
}

TEST(BetweenCodes, TwoZeroValuesAreAReportNotAPass) {
  const auto r = row(relative(0.03), 0.0, 0.0);
  EXPECT_EQ(r.kind, harness::RowKind::Report);
  EXPECT_FALSE(r.judged());
  EXPECT_NE(r.reason.find("both codes give 0"), std::string::npos);
}

TEST(BetweenCodes, AZeroReferenceAgainstANonZeroValueFails) {
  // Before, the plain difference 0.02 kg/s was set against the relative tolerance 0.03 and passed.
  const auto r = row(relative(0.03), 0.0, 0.02);
  EXPECT_TRUE(r.judged());
  EXPECT_TRUE(std::isinf(r.error));
  EXPECT_EQ(r.verdict(), "fail");
}

TEST(BetweenCodes, ProfileRowsScaleByTheLargestValueAndAbsoluteRowsTakeThePlainDifference) {
  auto b = relative(0.1);
  b.relative_to_largest = true;
  const auto band = row(b, 0.0, 0.05, 1.0);  // a zero band of a profile whose largest value is 1
  EXPECT_NEAR(band.error, 0.05, 1e-15);
  EXPECT_EQ(band.verdict(), "pass");
  EXPECT_EQ(row(b, 0.0, 0.05, 0.0).kind, harness::RowKind::Match);  // a zero profile, silodem not: fails
  EXPECT_EQ(row(b, 0.0, 0.05, 0.0).verdict(), "fail");
  auto a = relative(0.01);
  a.absolute = true;
  EXPECT_NEAR(row(a, 0.0, 0.005).error, 0.005, 1e-15);
  EXPECT_EQ(row(a, 0.0, 0.005).verdict(), "pass");
}

TEST(BetweenCodes, AReportedQuantityStaysReportedWhateverTheValues) {
  auto b = relative(0.03);
  b.report = "the speed piece is the flow's start";
  EXPECT_EQ(row(b, 0.9, 0.9).kind, harness::RowKind::Report);
}
