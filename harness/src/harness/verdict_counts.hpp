#pragma once
// The counts a verdict headline gives. The unit is a judged quantity: one (case, variant, code,
// quantity) with judged rows, which passes if all of them pass — so the 192 pairs of one collision
// variant are one quantity, with 192 sub-rows beside it. Report rows are counted apart, never as
// passes; skipped rows neither.
#include <map>
#include <string>
#include <vector>

#include "harness/check_row.hpp"

namespace harness {

/// Rows of one (case, variant, code, quantity) and one class: judged, report or skip.
struct QuantityLine {
  std::string case_name, variant, code, quantity;
  std::string cls;  // "judged", "report" or "skip"
  std::vector<const CheckRow*> rows;
  std::size_t passed = 0;  // judged rows that passed
  bool pass() const { return cls == "judged" && passed == rows.size(); }
};

/// Lines in the order their first row appears.
std::vector<QuantityLine> quantity_lines(const std::vector<CheckRow>& rows);

struct VerdictCounts {
  std::size_t variants = 0;
  std::size_t judged = 0, judged_passed = 0;  // quantities
  std::size_t rows = 0, rows_passed = 0;      // their judged sub-rows
  std::size_t reported = 0, report_rows = 0;  // report quantities and their rows
  std::size_t skipped_rows = 0;
  /// At least one quantity judged, and every judged quantity passed.
  bool all_pass() const { return judged > 0 && judged_passed == judged; }
};

struct Headline {
  VerdictCounts total;
  std::vector<std::pair<std::string, VerdictCounts>> cases;  // in the order the cases appear
};

Headline headline(const std::vector<CheckRow>& rows);

/// "85 of 85 judged quantities passed (7640 of 7640 judged sub-rows); 40 quantities (380 rows)
/// reported, not judged; 5 rows skipped".
std::string headline_sentence(const VerdictCounts& c);

}  // namespace harness
