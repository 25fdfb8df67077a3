#pragma once
// One between_codes row: silodem's value of a quantity against a reference code's, both from the
// same shared state, judged with the case's tolerance (compare.between_codes, docs/case-format.md).
#include <string>

#include "harness/check_row.hpp"
#include "harness/compare_case.hpp"

namespace harness {

/// The row "silodem vs <code>" for one (quantity, subject): expected = the reference code's value,
/// measured = silodem's, the error relative to the reference value (or to `largest`, the largest
/// value of its profile, with relative_to_largest), or their plain difference with `absolute`.
/// A relative tolerance needs a non-zero scale: with both values zero nothing was measured (a
/// report row, never a pass); with only the scale zero the error is infinite (a fail).
CheckRow between_row(const Between& bq, const std::string& case_name, const std::string& variant,
                     const std::string& code, const CheckRow& theirs, const CheckRow& ours, double largest);

}  // namespace harness
