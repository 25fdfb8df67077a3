#include "harness/between_codes.hpp"

#include <cmath>
#include <limits>

#include "harness/checks.hpp"

namespace harness {

CheckRow between_row(const Between& bq, const std::string& case_name, const std::string& variant,
                     const std::string& code, const CheckRow& theirs, const CheckRow& ours, double largest) {
  CheckRow x;
  x.case_name = case_name;
  x.variant = variant;
  x.code = "silodem vs " + code;
  x.quantity = theirs.quantity;
  x.subject = theirs.subject;
  x.expected = theirs.measured;  // the reference code's value
  x.measured = ours.measured;    // silodem's
  x.kind = RowKind::Match;
  x.tolerance = bq.tolerance;
  x.tolerance_source = bq.source;
  const double scale = bq.relative_to_largest ? largest : x.expected;
  std::string no_scale;
  if (bq.absolute) {
    x.error = x.measured - x.expected;
    x.note = "plain difference";
  } else if (scale != 0.0) {
    x.error = (x.measured - x.expected) / scale;
    if (bq.relative_to_largest) x.note = "difference / largest value of the profile";
  } else if (x.measured == 0.0) {
    no_scale = "both codes give 0, so a relative difference measures nothing (nothing happened to compare)";
  } else {
    x.error = std::numeric_limits<double>::infinity();
    x.note = "the reference code gives 0 where silodem does not: the relative difference is unbounded";
  }
  // A quantity without meaning for these grains is not judged between codes either.
  if (is_frictionless_report(theirs)) to_report(x, theirs.reason);
  else if (!bq.report.empty()) to_report(x, bq.report);
  else if (!no_scale.empty()) to_report(x, no_scale);
  else judge(x);
  return x;
}

}  // namespace harness
